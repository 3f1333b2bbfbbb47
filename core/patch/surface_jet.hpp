// A surface point with its exact first and second partial derivatives.
#pragma once

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

struct SurfaceJet {
  Vec3 p{0}, su{0}, sv{0}, suu{0}, suv{0}, svv{0};
};

// S += w C: a control point's share of the surface, w its basis function's jet.
inline void add_scaled(SurfaceJet& s, const Jet& w, const Vec3& c) {
  s.p += w.f * c;
  s.su += w.fu * c;
  s.sv += w.fv * c;
  s.suu += w.fuu * c;
  s.suv += w.fuv * c;
  s.svv += w.fvv * c;
}

}  // namespace pl
