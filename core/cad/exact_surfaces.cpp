#include "core/cad/exact_surfaces.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <glm/vec4.hpp>

#include "core/curve/bspline_curve.hpp"
#include "core/math/bernstein.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

using Row = std::vector<glm::dvec4>;

// Clamps one direction of a homogeneous control net (rows[k] is one curve along the direction,
// all on knots U of degree p with n points) at both ends of the range [U[p], U[n]] by inserting
// the end knots up to multiplicity p + 1, then drops what lies outside; maps the range to [0, 1].
void clamp_direction(int p, std::vector<double>& U, std::vector<Row>& rows) {
  const double a = U[p], b = U[rows.front().size()];
  for (double t : {a, b}) {
    std::vector<double> knots = U;
    for (Row& r : rows) {
      knots = U;
      while (std::count(knots.begin(), knots.end(), t) < p + 1) insert_knot(p, knots, r, t);
    }
    U = knots;
  }
  const std::size_t first = std::find(U.begin(), U.end(), a) - U.begin();
  const std::size_t last = std::find(U.begin(), U.end(), b) - U.begin() + p;  // b's p+1 copies
  std::vector<double> V(U.begin() + first, U.begin() + last + 1);
  const std::size_t n = V.size() - p - 1;
  for (Row& r : rows) r = Row(r.begin() + first, r.begin() + first + n);
  for (double& k : V) k = k == a ? 0.0 : k == b ? 1.0 : (k - a) / (b - a);
  U = std::move(V);
}

CadSurface spline_surface(const SplineGrid& g, const std::vector<Vec3>& points,
                          const std::vector<double>& weights) {
  const int p = g.p(), q = g.q();
  std::size_t nu = g.nu(), nv = g.nv();
  auto w = [&](std::size_t k) { return weights.empty() ? 1.0 : weights[k]; };
  // Along v first (rows i), then along u (columns j).
  std::vector<Row> rows(nu);
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j)
      rows[i].emplace_back(w(i * nv + j) * points[i * nv + j], w(i * nv + j));
  std::vector<double> kv = g.knots_v(), ku = g.knots_u();
  clamp_direction(q, kv, rows);
  nv = rows.front().size();
  std::vector<Row> cols(nv);
  for (std::size_t j = 0; j < nv; ++j)
    for (std::size_t i = 0; i < nu; ++i) cols[j].push_back(rows[i][j]);
  clamp_direction(p, ku, cols);
  nu = cols.front().size();
  CadSurface s;
  s.degree_u = p, s.degree_v = q, s.knots_u = ku, s.knots_v = kv, s.nu = nu, s.nv = nv;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const glm::dvec4 h = cols[j][i];
      s.points.push_back(Vec3(h) / h.w);
      if (!weights.empty()) s.weights.push_back(h.w);
    }
  return s;
}

CadSurface from_bezier_net(int m, int n, std::vector<Vec3> points) {
  CadSurface s;
  s.degree_u = m, s.degree_v = n;
  s.knots_u = uniform_knots(m, 1), s.knots_v = uniform_knots(n, 1);
  s.nu = m + 1, s.nv = n + 1;
  s.points = std::move(points);
  return s;
}

BezierPatch reversed_v(const BezierPatch& b) {
  const int m = b.degree_u(), n = b.degree_v();
  std::vector<Vec3> pts;
  for (int i = 0; i <= m; ++i)
    for (int j = n; j >= 0; --j) pts.push_back(b.at(i, j));
  return BezierPatch(m, n, std::move(pts));
}

}  // namespace

CadSurface bezier_surface(const BezierPatch& patch) {
  return from_bezier_net(patch.degree_u(), patch.degree_v(), patch.control_points());
}

CadSurface bspline_surface(const BSplinePatch& patch) {
  return spline_surface(patch.grid(), patch.control_points(), {});
}

CadSurface nurbs_surface(const NurbsPatch& patch) {
  return spline_surface(patch.grid(), patch.control_points(), patch.weights());
}

BezierPatch interpolate_polynomial(int m, int n, const std::function<Vec3(Vec2)>& f) {
  auto bernstein_matrix = [](int d) {
    Eigen::MatrixXd B(d + 1, d + 1);
    std::vector<double> row(d + 1);
    for (int a = 0; a <= d; ++a) {
      bernstein_all(d, double(a) / d, row);
      for (int i = 0; i <= d; ++i) B(a, i) = row[i];
    }
    return B;
  };
  const Eigen::MatrixXd Bu = bernstein_matrix(m), Bv = bernstein_matrix(n);
  const auto lu = Bu.partialPivLu(), lv = Bv.partialPivLu();
  std::vector<Vec3> pts((m + 1) * (n + 1));
  Eigen::MatrixXd F(m + 1, n + 1);
  std::vector<Vec3> samples((m + 1) * (n + 1));
  for (int a = 0; a <= m; ++a)
    for (int b = 0; b <= n; ++b) samples[a * (n + 1) + b] = f({double(a) / m, double(b) / n});
  for (int c = 0; c < 3; ++c) {
    for (int a = 0; a <= m; ++a)
      for (int b = 0; b <= n; ++b) F(a, b) = samples[a * (n + 1) + b][c];
    // F = Bu P Bv^T  =>  P = Bu^-1 F Bv^-T.
    const Eigen::MatrixXd X = lu.solve(F);
    const Eigen::MatrixXd P = lv.solve(X.transpose()).transpose();
    for (int i = 0; i <= m; ++i)
      for (int j = 0; j <= n; ++j) pts[i * (n + 1) + j][c] = P(i, j);
  }
  return BezierPatch(m, n, std::move(pts));
}

CadSurface join_bezier_cells(int cu, int cv, const std::vector<BezierPatch>& cells) {
  const int m = cells.front().degree_u(), n = cells.front().degree_v();
  CadSurface s;
  s.degree_u = m, s.degree_v = n;
  auto knots = [](int d, int cellsn) {
    std::vector<double> U(d + 1, 0.0);
    for (int k = 1; k < cellsn; ++k) U.insert(U.end(), d, double(k) / cellsn);
    U.insert(U.end(), d + 1, 1.0);
    return U;
  };
  s.knots_u = knots(m, cu), s.knots_v = knots(n, cv);
  s.nu = std::size_t(cu) * m + 1, s.nv = std::size_t(cv) * n + 1;
  s.points.assign(s.nu * s.nv, Vec3(0));
  // Higher-index cells first, so the lower-index cell's rows win on shared boundaries.
  for (int a = cu - 1; a >= 0; --a)
    for (int b = cv - 1; b >= 0; --b) {
      const BezierPatch& c = cells[a * cv + b];
      for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j)
          s.points[(std::size_t(a) * m + i) * s.nv + std::size_t(b) * n + j] = c.at(i, j);
    }
  return s;
}

namespace {

// One answer per registered patch type (patch_types.hpp): the surface as one B-spline surface
// where it is one, else none (the piece is fitted).
std::optional<CadSurface> exact_of(const BezierPatch& b) {
  return bezier_surface(b);
}
std::optional<CadSurface> exact_of(const BSplinePatch& b) {
  return bspline_surface(b);
}
std::optional<CadSurface> exact_of(const NurbsPatch& b) {
  return nurbs_surface(b);
}
// Hermite (Ferguson) and interpolating patches are bicubic polynomials over the whole square.
std::optional<CadSurface> bicubic(const Patch& patch) {
  return bezier_surface(interpolate_polynomial(3, 3, [&](Vec2 x) { return patch.evaluate(x).p; }));
}
std::optional<CadSurface> exact_of(const HermitePatch& p) {
  return bicubic(p);
}
std::optional<CadSurface> exact_of(const InterpolatingPatch& p) {
  return bicubic(p);
}
std::optional<CadSurface> exact_of(const CoonsNetworkPatch& c) {
  // Each cell is a polynomial of bidegree (5, 5): cubic Hermite blends (degree 3) times the
  // length terms S(v), lambda(v) (degree 1 and 3) and derivative blends (degree 2).
  const int cu = int(c.ns()) - 1, cv = int(c.nt()) - 1;
  std::vector<BezierPatch> cells;
  for (int a = 0; a < cu; ++a)
    for (int b = 0; b < cv; ++b)
      cells.push_back(interpolate_polynomial(
          5, 5, [&](Vec2 uv) { return c.cell_jet(std::size_t(a), std::size_t(b), uv).p; }));
  return join_bezier_cells(cu, cv, cells);
}
std::optional<CadSurface> exact_of(const PairJoinPatch& j) {
  // v in [0, 1/2] is B(u, 1 - 2v) (B with its v rows reversed), v in [1/2, 1] is A(u, 2v - 1).
  return join_bezier_cells(1, 2, {reversed_v(j.final_patch(1)), j.final_patch(0)});
}
// Rational blends of ribbons (Gregory, GB, transfinite schemes), a subdivision limit, and a
// composite whose middle is a blend: none is one B-spline surface.
template <OneOf<GregoryQuadPatch, GregoryTriPatch, GBPatch, GBRibbonPatch, GBInteriorPatch,
                RibbonPatch, CatmullClarkPatch, GapFillPatch>
              T>
std::optional<CadSurface> exact_of(const T&) {
  return std::nullopt;
}

}  // namespace

std::optional<CadSurface> exact_surface(const Patch& patch) {
  return visit_patch_type(patch, [](const auto& p) { return exact_of(p); });
}

}  // namespace pl
