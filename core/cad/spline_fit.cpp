#include "core/cad/spline_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/analysis/scene_analysis.hpp"  // angle_deg
#include "core/cad/fit_check.hpp"

namespace pl {

namespace {

// Parameters of `per_span` equal steps in every non-empty span of a clamped knot vector, and 1;
// span[k] is the index of the span parameter k lies in (1 lies in the last).
struct Samples {
  std::vector<double> t;
  std::vector<int> span;
};
Samples span_samples(const std::vector<double>& U, int per_span) {
  Samples s;
  const auto runs = knot_runs(U);
  for (std::size_t r = 0; r + 1 < runs.size(); ++r) {
    const double a = runs[r].value, b = runs[r + 1].value;
    for (int k = 0; k < per_span; ++k) {
      // k / per_span first: the same fraction gives the same parameter at any density.
      s.t.push_back(a + (b - a) * (double(k) / per_span));
      s.span.push_back(static_cast<int>(r));
    }
  }
  s.t.push_back(1.0);
  s.span.push_back(static_cast<int>(runs.size()) - 2);
  return s;
}

// Distinct knot values (span r is [breaks[r], breaks[r + 1]]).
std::vector<double> breaks(const std::vector<double>& U) {
  std::vector<double> b;
  for (const KnotRun& r : knot_runs(U)) b.push_back(r.value);
  return b;
}

// U with the midpoint of every marked span inserted (once). Returns false if none could be
// (too many spans already, or the span is too short to split).
bool bisect_spans(int p, std::vector<double>& U, const std::vector<char>& marked, int max_spans) {
  const std::vector<double> b = breaks(U);
  std::vector<double> add;
  int spans = static_cast<int>(b.size()) - 1;
  for (std::size_t r = 0; r + 1 < b.size(); ++r)
    if (marked[r] && spans < max_spans && b[r + 1] - b[r] > 1e-7) {
      add.push_back(0.5 * (b[r] + b[r + 1]));
      ++spans;
    }
  if (add.empty()) return false;
  std::vector<double> extra(p + 1, 0.0);
  extra.insert(extra.end(), add.begin(), add.end());
  extra.insert(extra.end(), p + 1, 1.0);
  U = merge_knots(p, U, extra);
  return true;
}

Eigen::MatrixXd basis_matrix(int p, const std::vector<double>& U, const std::vector<double>& t) {
  const std::size_t n = U.size() - p - 1;
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(t.size()), n);
  for (std::size_t a = 0; a < t.size(); ++a) {
    const CadBasis b = cad_basis(p, U, n, t[a]);
    for (int r = 0; r <= p; ++r) N(a, b.span - p + r) = b.value[r];
  }
  return N;
}

// Tensor-product evaluation on a grid (t_u x t_v), position and first derivatives.
void evaluate_grid(const CadSurface& s, const std::vector<double>& tu,
                   const std::vector<double>& tv, std::vector<SurfacePoint>& out) {
  std::vector<CadBasis> bv;
  for (double v : tv) bv.push_back(cad_basis(s.degree_v, s.knots_v, s.nv, v));
  out.resize(tu.size() * tv.size());
  std::vector<Vec3> row(s.nv), drow(s.nv);
  for (std::size_t a = 0; a < tu.size(); ++a) {
    const CadBasis bu = cad_basis(s.degree_u, s.knots_u, s.nu, tu[a]);
    for (std::size_t j = 0; j < s.nv; ++j) {
      Vec3 r(0), d(0);
      for (int k = 0; k <= s.degree_u; ++k) {
        const Vec3& P = s.at(bu.span - s.degree_u + k, j);
        r += bu.value[k] * P;
        d += bu.derivative[k] * P;
      }
      row[j] = r, drow[j] = d;
    }
    for (std::size_t b = 0; b < tv.size(); ++b) {
      SurfacePoint& o = out[a * tv.size() + b];
      o.p = o.su = o.sv = Vec3(0);
      for (int k = 0; k <= s.degree_v; ++k) {
        const std::size_t j = bv[b].span - s.degree_v + k;
        o.p += bv[b].value[k] * row[j];
        o.su += bv[b].value[k] * drow[j];
        o.sv += bv[b].derivative[k] * row[j];
      }
    }
  }
}

int span_count(const std::vector<double>& U) {
  return static_cast<int>(knot_runs(U).size()) - 1;
}

// The function's values on tensor grids, remembered across refinements: a refined grid keeps
// most of the previous one's parameters. Parameters are identified by their value rounded to
// 2^-40; values are kept in a table indexed by the parameters' indices.
class GridCache {
 public:
  explicit GridCache(const SurfaceFunction& f) : f_(f) {}
  void evaluate(const std::vector<double>& tu, const std::vector<double>& tv,
                std::vector<SurfacePoint>& out) {
    std::vector<int> iu(tu.size()), iv(tv.size());
    for (std::size_t a = 0; a < tu.size(); ++a) iu[a] = index(u_, tu[a]);
    for (std::size_t b = 0; b < tv.size(); ++b) iv[b] = index(v_, tv[b]);
    rows_.resize(u_.size());
    out.resize(tu.size() * tv.size());
    std::vector<Vec2> missing;
    std::vector<std::pair<int, int>> cell;
    for (std::size_t a = 0; a < tu.size(); ++a) {
      Row& row = rows_[iu[a]];
      row.value.resize(v_.size());
      row.known.resize(v_.size(), 0);
      for (std::size_t b = 0; b < tv.size(); ++b)
        if (!row.known[iv[b]]) {
          missing.emplace_back(tu[a], tv[b]);
          cell.emplace_back(iu[a], iv[b]);
        }
    }
    std::vector<SurfacePoint> fresh(missing.size());
    if (!missing.empty()) f_(missing, fresh);
    for (std::size_t k = 0; k < missing.size(); ++k) {
      rows_[cell[k].first].value[cell[k].second] = fresh[k];
      rows_[cell[k].first].known[cell[k].second] = 1;
    }
    for (std::size_t a = 0; a < tu.size(); ++a)
      for (std::size_t b = 0; b < tv.size(); ++b)
        out[a * tv.size() + b] = rows_[iu[a]].value[iv[b]];
  }

 private:
  struct Row {
    std::vector<SurfacePoint> value;
    std::vector<char> known;
  };
  static int index(std::map<int64_t, int>& m, double t) {
    const auto [it, fresh] = m.emplace(std::llround(std::ldexp(t, 40)), static_cast<int>(m.size()));
    return it->second;
  }
  const SurfaceFunction& f_;
  std::map<int64_t, int> u_, v_;
  std::vector<Row> rows_;
};

// The bounds of a fit, checked before `work` more grid points: the deadline (the first fit is
// always started), the fit's own bound, then the bound shared with the other fits of the export.
// Returns the bound that refuses it, or counts it in `done`. The first fit is bounded too: a
// face whose sides came with hundreds of spans asked for millions of grid points at once, a
// gigabyte of samples, before the bound was ever consulted. Refused there, the fit has no result.
std::optional<FitEnd> take_work(std::size_t& done, std::size_t work, const FitTolerance& tol) {
  if (done > 0 && std::chrono::steady_clock::now() >= tol.deadline) return FitEnd::Deadline;
  if (done + work > tol.max_work) return FitEnd::Work;
  if (tol.shared_work && tol.shared_work->fetch_add(work) + work > tol.max_shared_work)
    return FitEnd::SharedWork;
  done += work;
  return std::nullopt;
}

}  // namespace

int fit_samples_per_span(int p, int spans) {
  return 2 * spans + 1 >= p + 1 ? 2 : p;
}

CurveFit fit_curve(const CurveFunction& g, int p, const FitTolerance& tol) {
  CurveFit out;
  std::vector<double> U = uniform_knots(p, 1);
  while (true) {
    const int per = fit_samples_per_span(p, span_count(U));
    const std::size_t n = U.size() - p - 1;
    const Samples t = span_samples(U, per);
    // The samples and the check points, bounded before the work.
    if (const auto end = take_work(out.work, t.t.size() * 5, tol)) {
      out.end = *end;
      break;
    }
    std::vector<CurvePoint> G(t.t.size());
    g(t.t, G);
    // Unknowns: P_1 .. P_{n-2}; the ends are the curve's end points.
    const Eigen::MatrixXd N = basis_matrix(p, U, t.t);
    Eigen::MatrixXd R(N.rows(), 3);
    for (Eigen::Index a = 0; a < N.rows(); ++a) {
      const Vec3 r = G[a].p - N(a, 0) * G.front().p - N(a, n - 1) * G.back().p;
      R.row(a) << r.x, r.y, r.z;
    }
    const Eigen::MatrixXd X = N.middleCols(1, n - 2).colPivHouseholderQr().solve(R);
    CadCurve c;
    c.degree = p;
    c.knots = U;
    c.points.push_back(G.front().p);
    for (std::size_t i = 0; i + 2 < n; ++i) c.points.emplace_back(X(i, 0), X(i, 1), X(i, 2));
    c.points.push_back(G.back().p);
    // Check four times denser; bisect the spans that fail.
    const Samples check = span_samples(U, 4 * per);
    std::vector<CurvePoint> H(check.t.size());
    g(check.t, H);
    double dp = 0, da = 0;
    std::vector<char> failed(breaks(U).size() - 1, 0);
    for (std::size_t k = 0; k < check.t.size(); ++k) {
      const CurvePoint e = c.evaluate(check.t[k]);
      // Tangents are compared inside the curve only: at its ends a patch evaluated at a domain
      // vertex gives its differential there, which at a reflex corner of a concave GB face is
      // not the limit along the curve (the fitted end tangent is that limit by continuity).
      const bool end = k == 0 || k + 1 == check.t.size();
      const double ep = glm::length(e.p - H[k].p), ea = end ? 0.0 : angle_deg(e.d1, H[k].d1);
      dp = std::max(dp, ep), da = std::max(da, ea);
      if (ep > tol.position || ea > tol.normal_deg) failed[check.span[k]] = 1;
    }
    out.curve = std::move(c);
    out.position_deviation = dp, out.tangent_deviation_deg = da;
    out.check_points = static_cast<int>(check.t.size());
    out.converged = dp <= tol.position && da <= tol.normal_deg;
    out.end = out.converged ? FitEnd::Converged : FitEnd::Spans;
    if (out.converged || !bisect_spans(p, U, failed, tol.max_spans)) break;
  }
  return out;
}

SurfaceFit fit_surface(const SurfaceFunction& f, const std::array<CadCurve, 4>& input,
                       const FitTolerance& tol) {
  const int p = std::max({3, input[0].degree, input[2].degree});
  const int q = std::max({3, input[1].degree, input[3].degree});
  std::array<CadCurve, 4> sides;
  for (int s = 0; s < 4; ++s) sides[s] = input[s].elevated_to(s % 2 == 0 ? p : q);
  const std::vector<double> base_u = merge_knots(p, sides[0].knots, sides[2].knots);
  const std::vector<double> base_v = merge_knots(q, sides[1].knots, sides[3].knots);
  SurfaceFit out;
  GridCache cache(f);
  std::vector<double> U = merge_knots(p, base_u, uniform_knots(p, 1));
  std::vector<double> V = merge_knots(q, base_v, uniform_knots(q, 1));
  // The check grid is four times as dense as the samples for the verdict, but only twice while
  // the fit still misses: that is enough to see where it misses, and a fit that needs many
  // rounds (a singular corner of a GB face halves its deviation per round) paid the dense grid
  // at each. Once the sparse grid is met, the dense one decides; a fit it fails keeps to it.
  int check_density = 2;
  while (true) {
    const std::size_t nu = U.size() - p - 1, nv = V.size() - q - 1;
    // Boundary rows: the sides refined to the surface's knots.
    CadSurface s;
    s.degree_u = p, s.degree_v = q, s.knots_u = U, s.knots_v = V, s.nu = nu, s.nv = nv;
    s.points.assign(nu * nv, Vec3(0));
    const CadCurve s0 = sides[0].refined_to(U), s2 = sides[2].refined_to(U);
    const CadCurve s1 = sides[1].refined_to(V), s3 = sides[3].refined_to(V);
    for (std::size_t j = 0; j < nv; ++j)
      s.points[j] = s3.points[j], s.points[(nu - 1) * nv + j] = s1.points[j];
    for (std::size_t i = 0; i < nu; ++i)
      s.points[i * nv] = s0.points[i], s.points[i * nv + nv - 1] = s2.points[i];
    // Samples and the least-squares problem for the interior points. With a full tensor grid of
    // samples, min |Nu X Nv^T - F| over the interior block separates: X_in = Nu_in^+ R Nv_in^+T
    // with R = F - Nu X_boundary Nv^T.
    const int su = fit_samples_per_span(p, span_count(U)),
              sv = fit_samples_per_span(q, span_count(V));
    const Samples tu = span_samples(U, su), tv = span_samples(V, sv);
    Samples cu = span_samples(U, check_density * su), cv = span_samples(V, check_density * sv);
    // The samples and the check grid, bounded before the work.
    if (const auto end =
            take_work(out.work, tu.t.size() * tv.t.size() + cu.t.size() * cv.t.size(), tol)) {
      out.end = *end;
      break;
    }
    std::vector<SurfacePoint> F;
    cache.evaluate(tu.t, tv.t, F);
    const Eigen::MatrixXd Nu = basis_matrix(p, U, tu.t), Nv = basis_matrix(q, V, tv.t);
    const auto qr_u = Nu.middleCols(1, nu - 2).colPivHouseholderQr();
    const auto qr_v = Nv.middleCols(1, nv - 2).colPivHouseholderQr();
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd Xb = Eigen::MatrixXd::Zero(nu, nv);
      for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
          if (i == 0 || j == 0 || i == nu - 1 || j == nv - 1) Xb(i, j) = s.points[i * nv + j][c];
      Eigen::MatrixXd R(tu.t.size(), tv.t.size());
      for (std::size_t a = 0; a < tu.t.size(); ++a)
        for (std::size_t b = 0; b < tv.t.size(); ++b) R(a, b) = F[a * tv.t.size() + b].p[c];
      R -= Nu * Xb * Nv.transpose();
      const Eigen::MatrixXd Y = qr_u.solve(R);                            // (nu-2) x mv
      const Eigen::MatrixXd Xin = qr_v.solve(Y.transpose()).transpose();  // (nu-2) x (nv-2)
      for (std::size_t i = 1; i + 1 < nu; ++i)
        for (std::size_t j = 1; j + 1 < nv; ++j) s.points[i * nv + j][c] = Xin(i - 1, j - 1);
    }
    // Check; where the fit misses, bisect the spans along which the deviation varies
    // (fit_check.hpp).
    const auto check_on_grid = [&] {
      std::vector<SurfacePoint> truth, fit;
      cache.evaluate(cu.t, cv.t, truth);
      evaluate_grid(s, cu.t, cv.t, fit);
      return check_fit(truth, fit, {cu.t, check_density * su}, {cv.t, check_density * sv}, tol);
    };
    FitCheck check = check_on_grid();
    std::optional<FitEnd> refused;
    if (check_density == 2 && check.within(tol)) {
      check_density = 4;
      cu = span_samples(U, 4 * su), cv = span_samples(V, 4 * sv);
      refused = take_work(out.work, cu.t.size() * cv.t.size(), tol);
      if (!refused) check = check_on_grid();
    }
    out.surface = std::move(s);
    out.position_deviation = check.position, out.normal_deviation_deg = check.normal_deg;
    out.fit_samples = static_cast<int>(std::max(tu.t.size(), tv.t.size()));
    out.check_points = static_cast<int>(std::max(cu.t.size(), cv.t.size()));
    out.singular_normals = check.singular;
    out.converged = !refused && check.within(tol);
    out.end = out.converged ? FitEnd::Converged : refused ? *refused : FitEnd::Spans;
    if (out.converged || refused) break;
    if (check.pinned_bend) {
      out.end = FitEnd::Curve;
      break;
    }
    // The limit counts the spans this fit adds to those of the sides.
    const bool more_u = bisect_spans(p, U, check.split_u, tol.max_spans + span_count(base_u));
    const bool more_v = bisect_spans(q, V, check.split_v, tol.max_spans + span_count(base_v));
    if (!more_u && !more_v) break;
  }
  return out;
}

}  // namespace pl
