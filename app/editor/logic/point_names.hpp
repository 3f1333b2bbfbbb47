// Parses the names describe() gives points ("vertex 3", "edge 5 handle 1", "patch 0 point 7"),
// for the editor's --debug-point option and its tests.
#pragma once

#include <optional>
#include <string>

#include "app/document/point_ref.hpp"

namespace pl {

std::optional<PointRef> parse_point_name(const std::string& name);

}  // namespace pl
