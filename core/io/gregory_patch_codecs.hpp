// {"type": "gregory-quad", "points": [20 points]} and {"type": "gregory-tri", "points": [18
// points]}; point order in docs/patch-types.md and the patch headers.
#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_gregory_quad_patch(const JsonNode& node);
void write_gregory_quad_patch(const Patch& patch, nlohmann::json& out);
std::unique_ptr<Patch> read_gregory_tri_patch(const JsonNode& node);
void write_gregory_tri_patch(const Patch& patch, nlohmann::json& out);
}  // namespace pl
