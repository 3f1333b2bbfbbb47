#include "core/analysis/curve_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
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

// The length of the curve over [lo, hi] by one 16-point Gauss-Legendre rule; `span` carries the
// knot span between evaluations (scene_curve.hpp).
double piece_length(const SceneCurve& c, double lo, double hi, int& span) {
  const GaussLegendre& g = gauss();
  const double half = (hi - lo) / 2, mid = (hi + lo) / 2;
  double s = 0;
  for (int i = 0; i < kGaussPoints; ++i)
    s += g.w[i] * glm::length(evaluate(c, mid + half * g.x[i], span).d1);
  return half * s;
}

// Deepest halving: 4,096 pieces of a span, as the uniform refinement this replaces went.
constexpr int kMaxHalvings = 12;

// `whole` (the rule on [lo, hi]) refined where it needs it: a piece whose two halves sum to it
// within `tol` is done; otherwise each half is refined the same way. Only the pieces near a
// point where |C'| is not smooth (a cusp, where it vanishes) go deep, so a span costs a few
// dozen evaluations, not the thousands a uniform refinement of the whole span took there.
double refined_length(const SceneCurve& c, double lo, double hi, double whole, double tol,
                      int halvings, int& span) {
  const double mid = (lo + hi) / 2;
  const double left = piece_length(c, lo, mid, span), right = piece_length(c, mid, hi, span);
  if (std::abs(left + right - whole) <= tol || halvings == 0 || !std::isfinite(left + right))
    return left + right;
  return refined_length(c, lo, mid, left, tol, halvings - 1, span) +
         refined_length(c, mid, hi, right, tol, halvings - 1, span);
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
  // C' is a sum of the control points times basis derivatives of about the degree over the
  // span: its rounding error is about eps times the degree times the largest coordinate, over
  // the span's parameter length, so a span's length cannot agree to better than about eps p M.
  // Far from the origin (a scan in world coordinates) that is above 1e-13 of the length, and
  // asking for 1e-13 halved every span to the deepest level: thousands of evaluations each.
  double largest = 0;
  const bool own =
      c.type == CurveType::BSpline || c.type == CurveType::Nurbs || c.type == CurveType::Bezier;
  for (const Vec3& q : own ? c.points : spline_form(c).points)
    largest = std::max({largest, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  const double rounding = 64 * std::numeric_limits<double>::epsilon() * curve_degree(c) * largest;
  int span = -1;
  for (const auto& [a, b] : curve_spans(c)) {
    const double whole = piece_length(c, a, b, span);
    const double tol = std::max(1e-13 * std::abs(whole), rounding);
    total += refined_length(c, a, b, whole, tol, kMaxHalvings, span);
  }
  return total;
}

namespace {

// What a curve's samples show, taken from each sample as it is evaluated. Kept, the samples of a
// spline of 400,000 points (3.2 million at 8 per span) took 230 MB, written once and read back
// from memory for every figure: the cost per sample grew with the curve.
struct SampleFigures {
  std::array<double, 2> curvature{std::numeric_limits<double>::infinity(), 0};
  std::size_t nonfinite = 0;  // samples whose position or curvature is not finite
  int inflections = 0;
};

// The samples at per_span per span; `bad(t)` is called at the first one whose position,
// derivatives or curvature are not finite (it may throw). The figures are taken only if asked.
template <class Bad>
SampleFigures sample_figures(const SceneCurve& c, int per_span, bool figures, Bad&& bad) {
  SampleFigures r;
  // Inflections: the signed curvature in the curve's plane (none if it has no plane), whose sign
  // changes are counted once the largest |k| is known.
  const Vec3 n = figures ? plane_normal(spline_form(c).points) : Vec3(0);
  std::vector<double> k;
  if (n != Vec3(0)) k.reserve(curve_span_count(c) * per_span + 1);
  double kmax = 0;
  bool seen_bad = false;
  int span = -1;
  for_each_sample_parameter(c, per_span, [&](double t) {
    const CurvePoint p = evaluate(c, t, span);
    const double kappa = curve_curvature(p);
    if (!seen_bad && (!finite(p.p) || !finite(p.d1) || !finite(p.d2) || !std::isfinite(kappa))) {
      seen_bad = true;
      bad(t);
    }
    if (!figures) return;
    if (!std::isfinite(kappa) || !finite(p.p)) {
      ++r.nonfinite;
    } else {
      r.curvature[0] = std::min(r.curvature[0], kappa);
      r.curvature[1] = std::max(r.curvature[1], kappa);
    }
    if (n == Vec3(0)) return;
    const double speed = glm::length(p.d1);
    k.push_back(speed == 0 ? 0.0 : glm::dot(glm::cross(p.d1, p.d2), n) / (speed * speed * speed));
    if (std::isfinite(k.back())) kmax = std::max(kmax, std::abs(k.back()));
  });
  if (r.curvature[0] > r.curvature[1]) r.curvature = {0, 0};
  // Curvature below this is rounding noise of a straight piece: no sign there.
  const double zero = 1e-9 * kmax;
  int sign = 0;
  for (double x : k) {
    if (!std::isfinite(x) || std::abs(x) <= zero) continue;
    const int sx = x > 0 ? 1 : -1;
    if (sign != 0 && sx != sign) ++r.inflections;
    sign = sx;
  }
  return r;
}

SampleFigures unchecked_figures(const SceneCurve& c, int per_span) {
  return sample_figures(c, per_span, true, [](double) {});
}

// check_curve_finite's DataError for the first sample that is not finite, at parameter t.
[[noreturn]] void throw_not_finite(double t, std::size_t index, const std::string& source) {
  char at[32];
  std::snprintf(at, sizeof at, "%.9g", t);  // short, even for a knot of 1e153
  throw DataError(source, "curves[" + std::to_string(index) + "]",
                  "the curve is not finite at t = " + std::string(at) +
                      " (its numbers overflow when evaluated)");
}

SampleFigures checked_figures(const SceneCurve& c, int per_span, bool figures, std::size_t index,
                              const std::string& source) {
  return sample_figures(c, per_span, figures,
                        [&](double t) { throw_not_finite(t, index, source); });
}

CurveReport report_of(const SceneCurve& c, const std::string& name, const SampleFigures& f,
                      double length) {
  CurveReport r;
  r.name = name;
  r.type = std::string(curve_type_name(c.type));
  r.degree = curve_degree(c);
  r.control_points = static_cast<int>(c.points.size());
  r.spans = static_cast<int>(curve_span_count(c));
  r.length = length;
  r.curvature = f.curvature;
  r.nonfinite_samples = f.nonfinite;
  r.inflections = f.inflections;
  return r;
}

void check_length(double length, std::size_t index, const std::string& source) {
  if (!std::isfinite(length))
    throw DataError(source, "curves[" + std::to_string(index) + "]",
                    "the curve's length is not finite (its numbers overflow when evaluated)");
}

}  // namespace

int curve_inflections(const SceneCurve& c, int per_span) {
  return unchecked_figures(c, per_span).inflections;
}

CurveReport analyze_curve(const SceneCurve& c, const std::string& name, int per_span) {
  return report_of(c, name, unchecked_figures(c, per_span), curve_length(c));
}

void check_curve_finite(const SceneCurve& c, std::size_t index, int per_span,
                        const std::string& source) {
  // The samples first: a curve whose samples overflow is named at the first such sample.
  checked_figures(c, per_span, false, index, source);
  check_length(curve_length(c), index, source);
}

CurveReport checked_curve_report(const SceneCurve& c, std::size_t index, int per_span,
                                 const std::string& source) {
  const SampleFigures f = checked_figures(c, per_span, true, index, source);
  const double length = curve_length(c);
  check_length(length, index, source);
  return report_of(c, curve_name(c, index), f, length);
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

namespace {

// The box around the curves' control points (their spline form's: each curve lies in the hull of
// those, so its ends lie in the box).
std::pair<Vec3, Vec3> curves_box(std::span<const SceneCurve> curves) {
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const SceneCurve& c : curves) {
    // The spline types' points are their control points; the others' are turned into theirs.
    const bool own =
        c.type == CurveType::BSpline || c.type == CurveType::Nurbs || c.type == CurveType::Bezier;
    for (const Vec3& q : own ? c.points : spline_form(c).points)
      lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  return {lo, hi};
}

}  // namespace

double curves_size(std::span<const SceneCurve> curves) {
  if (curves.empty()) return 0.0;
  const auto [lo, hi] = curves_box(curves);
  return glm::length(hi - lo);
}

std::vector<JointReport> curve_joints(std::span<const SceneCurve> curves) {
  if (curves.empty()) return {};
  // Not a structured binding: the cell lambda below captures the corner, which clang before 16
  // refuses for a binding (the fuzz build compiles with clang).
  const std::pair<Vec3, Vec3> box = curves_box(curves);
  const Vec3 lo = box.first;
  const double tol = 1e-9 * glm::length(box.second - lo);
  // Each end with its derivatives pointing along the direction of travel out of the joint: the
  // end of a curve arrives as it runs; its start arrives when the curve is run backwards
  // (C' negated, C'' kept).
  struct End {
    int curve;
    bool start;
    CurvePoint p;
  };
  std::vector<End> ends;
  ends.reserve(2 * curves.size());
  for (std::size_t i = 0; i < curves.size(); ++i) {
    ends.push_back({int(i), true, evaluate(curves[i], curves[i].t_min())});
    ends.push_back({int(i), false, evaluate(curves[i], curves[i].t_max())});
  }
  // Ends closer than tol lie in the same or neighbouring cells of a grid of that spacing, so each
  // end is compared with the few ends near it, not with all of them. Cells are counted from the
  // box's corner (at most about 1e9 cells a side, exact in a 64-bit integer). A cell a little
  // wider than tol keeps two ends tol apart in neighbouring cells despite the rounding of the
  // division.
  const double cell = tol > 0 ? tol * (1 + 1e-6) : 1.0;
  using Cell = std::array<std::int64_t, 3>;
  auto cell_of = [&](const Vec3& p) {
    Cell k{};
    for (int a = 0; a < 3; ++a)
      k[a] = static_cast<std::int64_t>(std::clamp(std::floor((p[a] - lo[a]) / cell), -1.0, 2e9));
    return k;
  };
  // The ends sorted by cell (x, then y, then z). The ends of the three cells (x + dx, y + dy,
  // z - 1 .. z + 1) are then one run of that order, and for each (dx, dy) the run's start only
  // moves forward as the ends are visited in order: the sweep reads the array front to back. A
  // hash map of the cells, looked up 27 times per end at scattered places, missed the cache on
  // nearly every lookup once the ends of a large chain no longer fitted in it.
  struct Placed {
    Cell cell;
    Vec3 p;
    std::size_t end;
  };
  std::vector<Placed> placed;
  placed.reserve(ends.size());
  // An end that is not finite meets no other (its figures would be NaN).
  for (std::size_t i = 0; i < ends.size(); ++i)
    if (finite(ends[i].p.p)) placed.push_back({cell_of(ends[i].p.p), ends[i].p.p, i});
  std::sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.end < b.end;
  });
  // The pairs (i, j), i < j, in the order a comparison of every pair would find them.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::array<std::size_t, 9> run_start{};  // per (dx, dy): the first end not below its run
  for (const Placed& e : placed) {
    for (int q = 0; q < 9; ++q) {
      const Cell first{e.cell[0] + q / 3 - 1, e.cell[1] + q % 3 - 1, e.cell[2] - 1};
      const Cell last{first[0], first[1], e.cell[2] + 1};
      std::size_t& t = run_start[q];
      while (t < placed.size() && placed[t].cell < first) ++t;
      for (std::size_t u = t; u < placed.size() && placed[u].cell <= last; ++u) {
        const Placed& f = placed[u];
        if (f.end > e.end && glm::length(e.p - f.p) <= tol) pairs.emplace_back(e.end, f.end);
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<JointReport> out;
  for (const auto& [i, j] : pairs) {
    const End &e = ends[i], &f = ends[j];
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
