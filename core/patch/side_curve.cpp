#include "core/patch/side_curve.hpp"

namespace pl {

CurvePoint side_curve_point(const Patch& patch, int side, double t) {
  const Domain& domain = patch.domain();
  // Every domain side is a straight segment (Domain::side_point interpolates its end vertices
  // linearly), so its direction is constant.
  const Vec2 d = domain.side_point(side, 1.0) - domain.side_point(side, 0.0);
  const SurfaceJet s = patch.evaluate(domain.side_point(side, t));
  return {s.p, d.x * s.su + d.y * s.sv,
          d.x * d.x * s.suu + 2 * d.x * d.y * s.suv + d.y * d.y * s.svv};
}

CurvatureComb side_comb(const Patch& patch, int side, int teeth) {
  return curvature_comb([&](double t) { return side_curve_point(patch, side, t); }, teeth);
}

std::vector<CurvatureComb> side_combs(const Patch& patch, int teeth) {
  std::vector<CurvatureComb> combs;
  for (int side = 0; side < patch.domain().side_count(); ++side)
    combs.push_back(side_comb(patch, side, teeth));
  return combs;
}

}  // namespace pl
