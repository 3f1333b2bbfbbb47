// Vector types of the core: double precision everywhere (GLM's dvec*).
#pragma once

#include <glm/glm.hpp>

namespace pl {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

}  // namespace pl
