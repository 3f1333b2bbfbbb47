#include "core/cad/fit_check.hpp"

#include <algorithm>
#include <cmath>

#include "core/analysis/scene_analysis.hpp"  // angle_deg

namespace pl {

namespace {

// Whether the function has a normal at a check point (not a collapsed corner).
bool has_normal(const SurfacePoint& s) {
  const Vec3 n = glm::cross(s.su, s.sv);
  return glm::length(n) > 1e-14 * glm::length(s.su) * glm::length(s.sv);
}

Vec3 unit_or_zero(const Vec3& v) {
  const double l = glm::length(v);
  return l > 0 ? v / l : Vec3(0);
}

// The deviation at a check point as one vector, scaled so that the tolerance is 1: the position
// error over the position tolerance, and the difference of the unit normals over the tangent of
// the normal tolerance (about the angle over it; zero where the function has no normal).
struct ScaledDeviation {
  Vec3 position, normal;
};

double distance(const ScaledDeviation& a, const ScaledDeviation& b) {
  return glm::length(a.position - b.position) + glm::length(a.normal - b.normal);
}

}  // namespace

FitCheck check_fit(std::span<const SurfacePoint> truth, std::span<const SurfacePoint> fit,
                   const CheckAxis& u, const CheckAxis& v, const FitTolerance& tol) {
  const std::size_t mu = u.t.size(), mv = v.t.size();
  FitCheck c;
  c.split_u.assign(u.spans(), 0);
  c.split_v.assign(v.spans(), 0);
  std::vector<ScaledDeviation> dev(mu * mv);
  std::vector<char> missed(mu * mv, 0);
  const double normal_scale = 1 / std::tan(tol.normal_deg * M_PI / 180);
  for (std::size_t k = 0; k < mu * mv; ++k) {
    const double ep = glm::length(fit[k].p - truth[k].p);
    double en = 0;
    dev[k].position = (fit[k].p - truth[k].p) / tol.position;
    dev[k].normal = Vec3(0);
    if (has_normal(truth[k])) {
      const Vec3 nf = glm::cross(fit[k].su, fit[k].sv), nt = glm::cross(truth[k].su, truth[k].sv);
      en = angle_deg(nf, nt);
      dev[k].normal = (unit_or_zero(nf) - unit_or_zero(nt)) * normal_scale;
    } else {
      ++c.singular;
    }
    c.position = std::max(c.position, ep), c.normal_deg = std::max(c.normal_deg, en);
    missed[k] = !(ep <= tol.position && en <= tol.normal_deg);
  }
  // Whether a miss at (a, b) is a pinned bend (check_fit in the header): (a, b) lies in the span
  // next to a side, and the side's check point on the same line misses by the bend.
  const double half_turn = 0.5 * std::tan(tol.normal_deg * M_PI / 180);
  const auto pinned_bend = [&](std::size_t a, std::size_t b, bool in_u) {
    const CheckAxis& axis = in_u ? u : v;
    const std::size_t at = in_u ? a : b, end = axis.t.size() - 1;
    const int per = axis.per_span;
    for (const std::size_t side : {std::size_t(0), end}) {
      const std::size_t other = side == 0 ? std::size_t(per) : end - per;  // the span's far end
      if (side == 0 ? at > other : at < other) continue;
      const std::size_t k = in_u ? side * mv + b : a * mv + side;
      if (!missed[k]) continue;
      const double span = std::fabs(axis.t[other] - axis.t[side]);
      const double across = glm::length(in_u ? truth[k].su : truth[k].sv) * span;
      if (glm::length(fit[k].p - truth[k].p) > half_turn * across) return true;
    }
    return false;
  };
  // A missed check point's cell: how much the deviation changes along u and along v through it.
  for (std::size_t a = 0; a < mu; ++a)
    for (std::size_t b = 0; b < mv; ++b) {
      if (!missed[a * mv + b]) continue;
      if (pinned_bend(a, b, true) || pinned_bend(a, b, false)) {
        c.pinned_bend = true;
        continue;
      }
      const int ru = std::min(static_cast<int>(a) / u.per_span, u.spans() - 1);
      const int rv = std::min(static_cast<int>(b) / v.per_span, v.spans() - 1);
      double along_u = 0, along_v = 0;
      for (int x = ru * u.per_span; x < (ru + 1) * u.per_span; ++x)
        along_u += distance(dev[(x + 1) * mv + b], dev[x * mv + b]);
      for (int y = rv * v.per_span; y < (rv + 1) * v.per_span; ++y)
        along_v += distance(dev[a * mv + y + 1], dev[a * mv + y]);
      if (along_u >= 0.5 * along_v) c.split_u[ru] = 1;
      if (along_v >= 0.5 * along_u) c.split_v[rv] = 1;
    }
  return c;
}

}  // namespace pl
