#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_pair_join(const JsonNode& node);
void write_pair_join(const Patch& patch, nlohmann::json& out);
}  // namespace pl
