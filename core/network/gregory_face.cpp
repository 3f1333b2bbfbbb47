#include "core/network/gregory_face.hpp"

#include <stdexcept>

#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> quad(const FaceRibbons& r) {
  std::vector<Vec3> p(GregoryQuadPatch::kPointCount);
  for (int s = 0; s < 4; ++s) {
    const CubicRibbon& rib = r.sides[s];
    for (int j = 0; j < 3; ++j) p[GregoryQuadPatch::boundary_index(s, j)] = rib.boundary[j];
    for (int k = 0; k < 2; ++k) p[GregoryQuadPatch::twin_index(s, k)] = rib.inner[1 + k];
  }
  return std::make_unique<GregoryQuadPatch>(std::move(p));
}

std::unique_ptr<Patch> tri(const FaceRibbons& r) {
  std::vector<Vec3> p(GregoryTriPatch::kPointCount);
  for (int s = 0; s < 3; ++s) {
    const auto& b = r.sides[s].boundary;
    const auto& in = r.sides[s].inner;
    // Cubic to quartic: Q_j = (j/4) P_{j-1} + (1 - j/4) P_j.
    p[GregoryTriPatch::boundary_index(s, 0)] = b[0];
    p[GregoryTriPatch::boundary_index(s, 1)] = 0.25 * b[0] + 0.75 * b[1];
    p[GregoryTriPatch::boundary_index(s, 2)] = 0.5 * (b[1] + b[2]);
    p[GregoryTriPatch::boundary_index(s, 3)] = 0.75 * b[2] + 0.25 * b[3];
    for (int k = 0; k < 2; ++k)
      p[GregoryTriPatch::twin_index(s, k)] = b[1 + k] + 0.75 * (in[1 + k] - b[1 + k]);
  }
  return std::make_unique<GregoryTriPatch>(std::move(p));
}

}  // namespace

std::unique_ptr<Patch> gregory_face_patch(const FaceRibbons& ribbons) {
  switch (ribbons.sides.size()) {
    case 3:
      return tri(ribbons);
    case 4:
      return quad(ribbons);
    default:
      throw std::invalid_argument("Gregory patches have 3 or 4 sides, this face has " +
                                  std::to_string(ribbons.sides.size()));
  }
}

}  // namespace pl
