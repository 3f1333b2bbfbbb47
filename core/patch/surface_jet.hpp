// A surface point with its exact first and second partial derivatives.
#pragma once

#include "core/math/vec.hpp"

namespace pl {

struct SurfaceJet {
  Vec3 p{0}, su{0}, sv{0}, suu{0}, suv{0}, svv{0};
};

}  // namespace pl
