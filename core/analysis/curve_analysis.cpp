#include "core/analysis/curve_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/data_error.hpp"
#include "core/curve/curvature.hpp"

namespace pl {

namespace {

constexpr int kGaussPoints = 16;

// Nodes and weights of Gauss-Legendre quadrature on [-1, 1] (Newton on P_n).
struct GaussLegendre {
  std::array<double, kGaussPoints> x{}, w{};
  GaussLegendre() {
    const int n = kGaussPoints;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1, p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * dp * dp);
    }
  }
};

const GaussLegendre& gauss() {
  static const GaussLegendre g;
  return g;
}

double span_length(const SceneCurve& c, double a, double b, int pieces) {
  const GaussLegendre& g = gauss();
  double sum = 0;
  for (int k = 0; k < pieces; ++k) {
    const double lo = a + (b - a) * k / pieces, hi = a + (b - a) * (k + 1) / pieces;
    const double half = (hi - lo) / 2, mid = (hi + lo) / 2;
    double s = 0;
    for (int i = 0; i < kGaussPoints; ++i)
      s += g.w[i] * glm::length(evaluate(c, mid + half * g.x[i]).d1);
    sum += half * s;
  }
  return sum;
}

// A unit normal of the plane holding every control point, or zero if they are not in one plane
// (or on one line).
Vec3 plane_normal(const std::vector<Vec3>& pts) {
  const Vec3 o = pts.front();
  double size = 0;
  std::size_t far = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (glm::length(pts[i] - o) > size) size = glm::length(pts[i] - o), far = i;
  if (size == 0) return Vec3(0);
  const Vec3 u = (pts[far] - o) / size;
  Vec3 best(0);
  double best_len = 0;
  for (const Vec3& q : pts) {
    const Vec3 n = glm::cross(u, (q - o) / size);
    if (glm::length(n) > best_len) best_len = glm::length(n), best = n;
  }
  if (best_len < 1e-12) return Vec3(0);  // on one line
  const Vec3 n = best / best_len;
  for (const Vec3& q : pts)
    if (std::abs(glm::dot(q - o, n)) > 1e-12 * size) return Vec3(0);
  return n;
}

}  // namespace

double curve_length(const SceneCurve& c) {
  double total = 0;
  for (const auto& [a, b] : curve_spans(c)) {
    double prev = span_length(c, a, b, 1);
    for (int pieces = 2; pieces <= 4096; pieces *= 2) {
      const double next = span_length(c, a, b, pieces);
      const bool done = std::abs(next - prev) <= 1e-13 * std::abs(next);
      prev = next;
      if (done) break;
    }
    total += prev;
  }
  return total;
}

int curve_inflections(const SceneCurve& c, int per_span) {
  const Vec3 n = plane_normal(spline_form(c).points);
  if (n == Vec3(0)) return 0;
  std::vector<double> k;
  double kmax = 0;
  for (double t : curve_sample_parameters(c, per_span)) {
    const CurvePoint p = evaluate(c, t);
    const double s = glm::length(p.d1);
    k.push_back(s == 0 ? 0.0 : glm::dot(glm::cross(p.d1, p.d2), n) / (s * s * s));
    if (std::isfinite(k.back())) kmax = std::max(kmax, std::abs(k.back()));
  }
  // Curvature below this is rounding noise of a straight piece: no sign there.
  const double zero = 1e-9 * kmax;
  int changes = 0, sign = 0;
  for (double x : k) {
    if (!std::isfinite(x) || std::abs(x) <= zero) continue;
    const int sx = x > 0 ? 1 : -1;
    if (sign != 0 && sx != sign) ++changes;
    sign = sx;
  }
  return changes;
}

CurveReport analyze_curve(const SceneCurve& c, const std::string& name, int per_span) {
  CurveReport r;
  r.name = name;
  r.type = std::string(curve_type_name(c.type));
  r.degree = curve_degree(c);
  r.control_points = static_cast<int>(c.points.size());
  r.spans = static_cast<int>(curve_spans(c).size());
  r.length = curve_length(c);
  r.curvature = {std::numeric_limits<double>::infinity(), 0};
  for (double t : curve_sample_parameters(c, per_span)) {
    const CurvePoint p = evaluate(c, t);
    const double k = curve_curvature(p);
    if (!std::isfinite(k) || !std::isfinite(p.p.x + p.p.y + p.p.z)) {
      ++r.nonfinite_samples;
      continue;
    }
    r.curvature[0] = std::min(r.curvature[0], k);
    r.curvature[1] = std::max(r.curvature[1], k);
  }
  if (r.curvature[0] > r.curvature[1]) r.curvature = {0, 0};
  r.inflections = curve_inflections(c, per_span);
  return r;
}

void check_curve_finite(const SceneCurve& c, std::size_t index, int per_span,
                        const std::string& source) {
  auto finite = [](const Vec3& v) { return std::isfinite(v.x + v.y + v.z); };
  for (double t : curve_sample_parameters(c, per_span)) {
    const CurvePoint p = evaluate(c, t);
    if (!finite(p.p) || !finite(p.d1) || !finite(p.d2) || !std::isfinite(curve_curvature(p)))
      throw DataError(source, "curves[" + std::to_string(index) + "]",
                      "the curve is not finite at t = " + std::to_string(t) +
                          " (its numbers overflow when evaluated)");
  }
  if (!std::isfinite(curve_length(c)))
    throw DataError(source, "curves[" + std::to_string(index) + "]",
                    "the curve's length is not finite (its numbers overflow when evaluated)");
}

Vec3 curvature_vector(const CurvePoint& c) {
  const double s2 = glm::dot(c.d1, c.d1);
  if (s2 == 0) return Vec3(0);
  return (c.d2 - (glm::dot(c.d2, c.d1) / s2) * c.d1) / s2;
}

JointReport joint_figures(const CurvePoint& a, const CurvePoint& b) {
  JointReport r;
  r.gap = glm::length(a.p - b.p);
  r.tangent_angle_deg =
      std::atan2(glm::length(glm::cross(a.d1, b.d1)), glm::dot(a.d1, b.d1)) * 180.0 / M_PI;
  const Vec3 ka = curvature_vector(a), kb = curvature_vector(b);
  r.curvature_jump = glm::length(ka - kb);
  r.curvature = {glm::length(ka), glm::length(kb)};
  return r;
}

int joint_continuity(const JointReport& j, double size, double angle_deg, double relative) {
  if (!(j.tangent_angle_deg <= angle_deg)) return 0;
  const double kappa = std::max(j.curvature[0], j.curvature[1]);
  const double straight = size > 0 ? relative / size : 0.0;
  if (j.curvature_jump <= relative * kappa || (kappa <= straight && j.curvature_jump <= straight))
    return 2;
  return 1;
}

double curves_size(std::span<const SceneCurve> curves) {
  if (curves.empty()) return 0.0;
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const SceneCurve& c : curves)
    for (const Vec3& q : spline_form(c).points) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

std::vector<JointReport> curve_joints(std::span<const SceneCurve> curves) {
  const double tol = 1e-9 * curves_size(curves);
  // Each end with its derivatives pointing along the direction of travel out of the joint: the
  // end of a curve arrives as it runs; its start arrives when the curve is run backwards
  // (C' negated, C'' kept).
  struct End {
    int curve;
    bool start;
    CurvePoint p;
  };
  std::vector<End> ends;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    ends.push_back({int(i), true, evaluate(curves[i], curves[i].t_min())});
    ends.push_back({int(i), false, evaluate(curves[i], curves[i].t_max())});
  }
  std::vector<JointReport> out;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size(); ++j) {
      const End &e = ends[i], &f = ends[j];
      if (glm::length(e.p.p - f.p.p) > tol) continue;
      if (e.curve == f.curve && e.start == f.start) continue;
      // Travel from the arriving end into the leaving one: an end arrives as is, a start
      // arrives reversed; a start leaves as is, an end leaves reversed.
      CurvePoint arrive = e.p, leave = f.p;
      if (e.start) arrive.d1 = -arrive.d1;
      if (!f.start) leave.d1 = -leave.d1;
      JointReport r = joint_figures(arrive, leave);
      r.curves = {e.curve, f.curve};
      r.at_start = {e.start, f.start};
      r.position = e.p.p;
      out.push_back(r);
    }
  return out;
}

}  // namespace pl
