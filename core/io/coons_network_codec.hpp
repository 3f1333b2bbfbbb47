#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_coons_network(const JsonNode& node);
void write_coons_network(const Patch& patch, nlohmann::json& out);
}  // namespace pl
