#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_gap_fill(const JsonNode& node);
void write_gap_fill(const Patch& patch, nlohmann::json& out);
}  // namespace pl
