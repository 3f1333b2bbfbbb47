#include "core/patch/patch.hpp"

#include <cassert>

namespace pl {

SurfaceJet combine(std::span<const Vec3> points, std::span<const Jet> phi) {
  assert(points.size() == phi.size());
  SurfaceJet s;
  for (std::size_t k = 0; k < points.size(); ++k) add_scaled(s, phi[k], points[k]);
  return s;
}

Vec3 Patch::boundary_point(int side, double t) const {
  return boundary_curves().at(side).point(t);
}

SurfaceJet Patch::evaluate(Vec2 x) const {
  std::vector<Jet> phi(size());
  basis(x, phi);
  return combine(points_, phi);
}

void Patch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  std::vector<Jet> phi(size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    basis(xs[i], phi);
    out[i] = phi[k];
  }
}

}  // namespace pl
