#include "core/cad/cad_pieces.hpp"

#include <cmath>

#include "core/base/data_error.hpp"
#include "core/cad/exact_surfaces.hpp"
#include "core/network/scene_parts.hpp"
#include "core/patch/exact_boundary.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/patch/patch_types.hpp"
#include "core/scene/surface_names.hpp"

namespace pl {

namespace {

const DomainQuad kUnitSquare{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};

// The part [t0, t1] of a Bézier curve, reparameterised to [0, 1] (t0 > t1: reversed).
BezierCurve sub_curve(const BezierCurve& c, double t0, double t1) {
  const double a = std::min(t0, t1), b = std::max(t0, t1);
  BezierCurve part = c;
  if (b < 1) part = part.split(b).first;
  if (a > 0) part = part.split(a / b).second;
  return t0 <= t1 ? part : part.reversed();
}

// The curve of the lowest degree that is exactly `c` (a degree-elevated curve, such as a cubic
// network edge on a quartic Gregory triangle side, is reduced back): reduced while elevating the
// reduction gives the control points again, to rounding.
BezierCurve lowest_degree(const BezierCurve& c) {
  BezierCurve best = c;
  while (best.degree() > 1) {
    const std::vector<Vec3>& P = best.control_points();
    const int n = best.degree();
    std::vector<Vec3> Q(
        n);  // the inverse of elevation from the start: P_i = (i Q_{i-1} + (n-i) Q_i) / n
    Q[0] = P[0];
    for (int i = 1; i < n; ++i) Q[i] = (double(n) * P[i] - double(i) * Q[i - 1]) / double(n - i);
    double size = 0, err = 0;
    for (const Vec3& p : P) size = std::max(size, glm::length(p - P[0]));
    const BezierCurve elevated = BezierCurve(Q).elevated();
    const std::vector<Vec3>& E = elevated.control_points();
    for (int i = 0; i <= n; ++i) err = std::max(err, glm::length(E[i] - P[i]));
    if (!(err <= 1e-13 * size)) break;
    Q.back() = P.back();  // the end point exactly
    best = BezierCurve(std::move(Q));
  }
  return best;
}

// The domain side a segment [a, b] lies on, with its side parameters; nullopt if none.
struct OnSide {
  int side;
  double t0, t1;
};
std::optional<OnSide> side_of(const Domain& d, Vec2 a, Vec2 b) {
  const std::vector<Vec2> P = domain_polygon(d);
  double size = 0;
  for (const Vec2& p : P) size = std::max(size, glm::length(p - P[0]));
  const double eps = 1e-10 * size;
  for (int s = 0; s < d.side_count(); ++s) {
    const Vec2 p0 = d.side_point(s, 0), p1 = d.side_point(s, 1), e = p1 - p0;
    const double ee = glm::dot(e, e);
    auto param = [&](Vec2 x, double& t) {
      t = glm::dot(x - p0, e) / ee;
      return t > -1e-12 && t < 1 + 1e-12 && glm::length(p0 + t * e - x) <= eps;
    };
    double ta, tb;
    if (param(a, ta) && param(b, tb))
      return OnSide{s, std::clamp(ta, 0.0, 1.0), std::clamp(tb, 0.0, 1.0)};
  }
  return std::nullopt;
}

// Pieces of a patch without a single exact form: its domain split into convex quadrilaterals.
void add_split_pieces(const std::shared_ptr<const Patch>& patch, const std::string& owner,
                      std::vector<CadPiece>& out) {
  const std::vector<DomainQuad> quads = split_into_quads(domain_polygon(patch->domain()));
  const bool exact_sides = boundary_curves_are_exact(*patch);
  std::vector<BezierCurve> curves;
  if (exact_sides)
    for (const BezierCurve& c : patch->boundary_curves()) curves.push_back(lowest_degree(c));
  int degree = 3;
  for (const BezierCurve& c : curves) degree = std::max(degree, c.degree());
  for (std::size_t k = 0; k < quads.size(); ++k) {
    CadPiece piece;
    piece.owner = owner;
    piece.name = piece_name(owner, quads.size(), k);
    piece.patch = patch;
    piece.quad = quads[k];
    piece.degree = degree;
    if (exact_sides) {
      const DomainQuad& q = quads[k];
      const std::array<std::pair<Vec2, Vec2>, 4> ends{
          {{q[0], q[1]}, {q[1], q[2]}, {q[3], q[2]}, {q[0], q[3]}}};
      for (int s = 0; s < 4; ++s)
        if (const auto on = side_of(patch->domain(), ends[s].first, ends[s].second))
          piece.known_sides[s] = CadCurve::from_bezier(sub_curve(curves[on->side], on->t0, on->t1));
    }
    out.push_back(std::move(piece));
  }
}

CadPiece exact_piece(std::shared_ptr<const Patch> patch, std::string owner, std::string name,
                     DomainQuad quad, CadSurface surface) {
  CadPiece p;
  p.owner = std::move(owner);
  p.name = std::move(name);
  p.patch = std::move(patch);
  p.quad = quad;
  p.exact = std::move(surface);
  return p;
}

// A Catmull-Clark face whose limit is a bicubic polynomial: reproduced from 16 samples, checked
// at 81 others to 1e-12 of the face's size.
std::optional<CadSurface> bicubic_face(const Patch& face) {
  const auto value = [&](Vec2 x) { return face.evaluate(x).p; };
  const CadSurface s = bezier_surface(interpolate_polynomial(3, 3, value));
  double size = 0;
  for (const Vec3& p : s.points) size = std::max(size, glm::length(p - s.points[0]));
  // The check grid avoids the interpolation nodes (k/3): 9 x 9 points at (k + 0.5) / 9.
  double worst = 0;
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) {
      const Vec2 x((a + 0.5) / 9, (b + 0.5) / 9);
      worst = std::max(worst, glm::length(s.evaluate(x.x, x.y).p - value(x)));
    }
  if (worst <= 1e-12 * std::max(size, 1e-300)) return s;
  return std::nullopt;
}

void add_patch_pieces(const std::shared_ptr<const Patch>& patch, const std::string& owner,
                      std::vector<CadPiece>& out) {
  if (auto exact = exact_surface(*patch)) {
    out.push_back(exact_piece(patch, owner, owner, kUnitSquare, std::move(*exact)));
    return;
  }
  if (const auto* g = patch_as<GapFillPatch>(*patch)) {
    // q over u in [0, 1/3], the fill over [1/3, 2/3], r over [2/3, 1] (gap_fill_patch.hpp).
    const double third = 1.0 / 3, two = 2.0 / 3;
    out.push_back(exact_piece(patch, owner, owner + ".q",
                              {Vec2(0, 0), Vec2(third, 0), Vec2(third, 1), Vec2(0, 1)},
                              bspline_surface(g->q())));
    CadPiece fill;
    fill.owner = owner;
    fill.name = owner + ".fill";
    fill.patch = patch;
    fill.quad = {Vec2(third, 0), Vec2(two, 0), Vec2(two, 1), Vec2(third, 1)};
    fill.degree = 3;
    out.push_back(std::move(fill));
    out.push_back(exact_piece(patch, owner, owner + ".r",
                              {Vec2(two, 0), Vec2(1, 0), Vec2(1, 1), Vec2(two, 1)},
                              bspline_surface(g->r())));
    return;
  }
  if (const auto* cc = patch_as<CatmullClarkPatch>(*patch)) {
    auto faces = cc->face_patches();
    for (std::size_t k = 0; k < faces.size(); ++k) {
      std::shared_ptr<const Patch> face = std::move(faces[k]);
      const std::string name = owner + "." + std::to_string(k);
      if (auto s = bicubic_face(*face)) {
        out.push_back(exact_piece(face, owner, name, kUnitSquare, std::move(*s)));
      } else {
        CadPiece p;
        p.owner = owner;
        p.name = name;
        p.patch = face;
        p.quad = kUnitSquare;
        out.push_back(std::move(p));
      }
    }
    return;
  }
  add_split_pieces(patch, owner, out);
}

}  // namespace

std::vector<CadPiece> cad_pieces(const Scene& scene, std::optional<FaceScheme> scheme,
                                 const std::string& source) {
  std::vector<CadPiece> out;
  const SceneParts parts = scene_parts(scene, scheme, source);
  for (std::size_t i = 0; i < parts.filling.faces.size(); ++i) {
    const FacePatch& fp = parts.filling.faces[i];
    try {
      add_patch_pieces(fp.patch, parts.face_names[i], out);
    } catch (const std::invalid_argument& e) {
      throw DataError(source, "network.faces[" + std::to_string(fp.face) + "]",
                      std::string("cannot export: ") + e.what());
    }
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    try {
      add_patch_pieces(std::shared_ptr<const Patch>(scene.patches[i].patch->clone()),
                       parts.patch_names[i], out);
    } catch (const std::invalid_argument& e) {
      throw DataError(source, "patches[" + std::to_string(i) + "]",
                      std::string("cannot export: ") + e.what());
    }
  }
  return out;
}

SurfaceFunction piece_function(const CadPiece& piece) {
  return [patch = piece.patch, quad = piece.quad](std::span<const Vec2> uv,
                                                  std::span<SurfacePoint> out) {
    std::vector<Vec2> x(uv.size());
    for (std::size_t k = 0; k < uv.size(); ++k) x[k] = quad_point(quad, uv[k]);
    std::vector<SurfaceJet> s(uv.size());
    // The patch on its own: a fit's grids are its piece's alone, so a basis block kept for them
    // (shared_basis.hpp) would serve no other face, and a GB face's basis evaluated point by
    // point to fill one took 20 us a sample at 64 sides; on its own the face runs its SIMD form.
    const SharedBasisBypass alone;
    patch->evaluate_many(x, s);
    for (std::size_t k = 0; k < uv.size(); ++k) {
      const Vec2 du = quad_du(quad, uv[k]), dv = quad_dv(quad, uv[k]);
      out[k] = {s[k].p, du.x * s[k].su + du.y * s[k].sv, dv.x * s[k].su + dv.y * s[k].sv};
    }
  };
}

}  // namespace pl
