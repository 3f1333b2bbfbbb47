#pragma once

#include "core/io/patch_codec.hpp"

namespace pl {
std::unique_ptr<Patch> read_catmull_clark(const JsonNode& node);
void write_catmull_clark(const Patch& patch, nlohmann::json& out);
}  // namespace pl
