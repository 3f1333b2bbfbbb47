#include "core/network/ribbon_face.hpp"

#include <stdexcept>
#include <string>

#include "core/network/gb_face.hpp"

namespace pl {

std::vector<RibbonSide> explicit_ribbons(const FaceRibbons& ribbons) {
  std::vector<RibbonSide> sides;
  for (const CubicRibbon& r : ribbons.sides) {
    RibbonSide s;
    s.curve.type = s.cross.type = CurveType::Bezier;
    s.curve.points.assign(r.boundary.begin(), r.boundary.end());
    for (int j = 0; j < 4; ++j) s.cross.points.push_back(3.0 * (r.inner[j] - r.boundary[j]));
    sides.push_back(std::move(s));
  }
  return sides;
}

std::unique_ptr<RibbonPatch> ribbon_face_patch(const FaceRibbons& ribbons,
                                               transfinite::RibbonScheme scheme, double fullness) {
  const std::vector<double> turning = face_turning_angles(ribbons);
  const int n = static_cast<int>(turning.size());
  for (int i = 0; i < n; ++i)
    if (!(turning[i] > 0))
      throw std::invalid_argument("the corner at loop[" + std::to_string((i + 1) % n) +
                                  "] is reflex: the " +
                                  std::string(transfinite::ribbon_scheme_name(scheme)) +
                                  " scheme fills convex faces only (use gb for concave faces)");
  RibbonPatchOptions options;
  options.check_corners = false;  // compatible by construction (face_ribbons.hpp)
  if (transfinite::has_central_point(scheme)) options.fullness = fullness;
  return std::make_unique<RibbonPatch>(scheme, explicit_ribbons(ribbons), options);
}

}  // namespace pl
