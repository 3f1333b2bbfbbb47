#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_gb_ribbon_patch(const JsonNode& node);
void write_gb_ribbon_patch(const Patch& patch, nlohmann::json& out);
}  // namespace pl
