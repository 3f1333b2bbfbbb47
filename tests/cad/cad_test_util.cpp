#include "cad_test_util.hpp"

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>

#include "core/analysis/scene_analysis.hpp"  // angle_deg

namespace pl::test {

Deviation surface_deviation(const CadPiece& piece, const BRepAdaptor_Surface& s,
                            const std::vector<double>& tu, const std::vector<double>& tv) {
  Deviation d;
  for (double u : tu)
    for (double v : tv) {
      gp_Pnt p;
      gp_Vec du, dv;
      s.D1(u, v, p, du, dv);
      const PieceTruth t = piece_truth(piece, {u, v});
      d.position = std::max(d.position, glm::length(Vec3(p.X(), p.Y(), p.Z()) - t.p));
      const Vec3 nt = glm::cross(t.su, t.sv);
      if (glm::length(nt) > 1e-14 * glm::length(t.su) * glm::length(t.sv)) {
        const gp_Vec n = du.Crossed(dv);
        d.normal_deg = std::max(d.normal_deg, angle_deg(Vec3(n.X(), n.Y(), n.Z()), nt));
      }
      ++d.points;
    }
  return d;
}

CurveFunction side_curve(const SurfaceFunction& f, int s) {
  return [f, s](std::span<const double> t, std::span<CurvePoint> out) {
    std::vector<Vec2> uv;
    for (double x : t)
      uv.push_back(s == 0 ? Vec2(x, 0) : s == 1 ? Vec2(1, x) : s == 2 ? Vec2(x, 1) : Vec2(0, x));
    std::vector<SurfacePoint> sp(t.size());
    f(uv, sp);
    for (std::size_t k = 0; k < t.size(); ++k)
      out[k] = {sp[k].p, s % 2 ? sp[k].sv : sp[k].su, Vec3(0)};
  };
}

CheckGrid fitted_check_grid(const BRepAdaptor_Surface& s) {
  const Handle(Geom_BSplineSurface) b = s.BSpline();
  auto knots = [](const TColStd_Array1OfReal& k) {
    std::vector<double> out;
    for (int i = k.Lower(); i <= k.Upper(); ++i) out.push_back(k(i));
    return out;
  };
  const std::vector<double> ku = knots(b->UKnots()), kv = knots(b->VKnots());
  const int su = fit_samples_per_span(b->UDegree(), int(ku.size()) - 1);
  const int sv = fit_samples_per_span(b->VDegree(), int(kv.size()) - 1);
  return {per_span_params(ku, 4 * su), per_span_params(kv, 4 * sv)};
}

}  // namespace pl::test
