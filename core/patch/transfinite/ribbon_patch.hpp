// A multi-sided patch given by explicit ribbons (scene type "ribbons"; docs/patch-types.md):
// per side a boundary curve P_i and a cross-boundary derivative curve D_i (Bézier, B-spline or
// NURBS), filled by one of the ribbon-based transfinite schemes (ribbon_scheme.hpp) over a convex
// polygonal domain. Not the "gb-ribbons" type, which is a Generalized Bézier patch with
// independent ribbons of control points.
//
// Control points: side after side, the curve's control points, then the cross derivative's
// control vectors (kind Inner: they are derivatives, not positions), then the explicit midpoint
// of the midpoint schemes if one is set (kind Central). The surface is linear in all of them (for
// fixed NURBS weights and a fixed domain), which is the basis of a moved point's axpy.
//
// Domain vertices (side i from vertex i-1 to vertex i) are the limits of the schemes' rational
// forms: there the patch returns the corner P_i(1), the first derivatives that reproduce both
// sides' end tangents exactly, and the second derivatives the scheme has 1e-4 of the domain's
// size from the vertex towards its centre (at a vertex they depend on the direction of approach,
// so no value is exact; these are finite and within about 1e-4 of the radial limit).
#pragma once

#include <optional>
#include <vector>

#include "core/curve/scene_curve.hpp"
#include "core/domain/convex_polygon.hpp"
#include "core/patch/patch.hpp"
#include "core/patch/transfinite/ribbon_scheme.hpp"

namespace pl {

struct RibbonSide {
  SceneCurve curve;  // along the side, in loop order (bezier, bspline or nurbs)
  SceneCurve cross;  // the derivative across the side, pointing into the face
};

struct RibbonPatchOptions {
  // The corner twists (transfinite::TwistEstimate): exact, or the research library's forward
  // difference (for reproducing its numbers only).
  transfinite::TwistEstimate twists = transfinite::TwistEstimate::Exact;
  // Midpoint schemes: the point the surface passes through at the domain centre. None: the
  // average of the side interpolants' midpoints, (1/n) sum_i (P_i(1/2) + D_i(1/2) / 4).
  std::optional<Vec3> midpoint;
  // Midpoint schemes without an explicit midpoint: the fullness f puts the midpoint at
  // c + f (m - c), c the average of the corners and m the default midpoint above; 1 is the
  // default, 0 pulls the middle to the corners' average, above 1 the face bulges more.
  double fullness = 1;
  // The domain polygon (counter-clockwise, strictly convex). None: the scheme's default, the
  // regular n-gon of ConvexPolygonDomain::regular, or for the side-based scheme the polygon the
  // research library builds from the curves' arc lengths and corner angles (its "angular"
  // domain; the regular n-gon where that comes out not convex).
  std::optional<std::vector<Vec2>> domain;
  // Check that the ribbons meet at the corners (ribbon_corner_problem) and that the face is
  // convex; off only for ribbons known to be compatible by construction (network faces).
  bool check_corners = true;
};

// Relative tolerances of the corner check: ends of consecutive curves within kCornerGap times
// the diagonal of the ribbons' bounding box; a cross derivative at a corner equal to the
// neighbouring side's end tangent within kCornerTangent times the longer of the two.
inline constexpr double kCornerGap = 1e-9;
inline constexpr double kCornerTangent = 1e-6;

// Why the ribbons are not compatible at corner i (between side i and side i+1), or "". Checks:
// P_i(1) = P_{i+1}(0); D_{i+1}(0) = -P_i'(1); D_i(1) = P_{i+1}'(0).
std::string ribbon_corner_problem(const std::vector<RibbonSide>& sides, int corner);
// The first corner where the boundary turns against the others (a reflex corner, judged around
// the Newell normal of the corners), or -1.
int ribbon_reflex_corner(const std::vector<RibbonSide>& sides);

class RibbonPatch : public PatchType<RibbonPatch> {
 public:
  static constexpr const char* kType = "ribbons";
  static constexpr int kMaxSides = 64;

  // Throws std::invalid_argument (naming the side or corner) for fewer than 3 or more than
  // kMaxSides sides, a curve type other than bezier/bspline/nurbs, incompatible corners, a
  // reflex corner, a non-convex domain, or a midpoint for a scheme without one.
  RibbonPatch(transfinite::RibbonScheme scheme, std::vector<RibbonSide> sides,
              RibbonPatchOptions options = {});

  transfinite::RibbonScheme scheme() const { return scheme_; }
  const std::vector<RibbonSide>& sides() const { return sides_; }
  const RibbonPatchOptions& options() const { return options_; }
  // Whether the domain is the scheme's default (not written to files): the regular n-gon, or for
  // the side-based scheme the polygon built from the curves (transfinite/angular_domain.hpp),
  // rebuilt whenever a curve point moves.
  bool default_domain() const { return !options_.domain.has_value(); }
  // Whether the domain is built from the curves and so moves with a curve point (the side-based
  // scheme's default): the surface is then not linear in the curves' points.
  bool domain_follows_curves() const { return domain_follows_curves(scheme_, options_); }
  static bool domain_follows_curves(transfinite::RibbonScheme scheme,
                                    const RibbonPatchOptions& options) {
    return scheme == transfinite::RibbonScheme::SideBased && !options.domain;
  }

  const Domain& domain() const override { return domain_; }
  const ConvexPolygonDomain& polygon() const { return domain_; }
  ControlPointKind kind(std::size_t k) const override;
  void set_control_point(std::size_t k, const Vec3& p) override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // Each side's curve as one Bézier curve: exact for Bézier sides; a B-spline or NURBS side is
  // returned as the Bézier curve of its control points (same ends); boundary_point is exact.
  std::vector<BezierCurve> boundary_curves() const override;
  Vec3 boundary_point(int side, double t) const override;
  // Whether every side's curve is a Bézier curve (then boundary_curves() is exact).
  bool bezier_sides() const;

  // The central control point C of the midpoint schemes (zero for the others).
  const Vec3& central_point() const { return central_; }

 private:
  struct DomainChoice {
    ConvexPolygonDomain polygon;
    Vec2 centre;  // orients the parameters' inward normals
  };
  static DomainChoice choose_domain(transfinite::RibbonScheme scheme,
                                    const std::vector<RibbonSide>& sides,
                                    const RibbonPatchOptions& options);
  void set_domain(DomainChoice d);
  void rebuild();
  // The ribbons of the given control points (all of them, in patch order).
  transfinite::RibbonSet ribbon_set_of(const std::vector<Vec3>& points) const;
  // The surface of the given control points (all of them, in patch order).
  SurfaceJet evaluate_points(const std::vector<Vec3>& points, Vec2 x) const;

  transfinite::RibbonScheme scheme_;
  std::vector<RibbonSide> sides_;
  RibbonPatchOptions options_;
  ConvexPolygonDomain domain_;
  transfinite::PolygonParameters params_;
  std::vector<std::size_t> offsets_;  // per side: index of its first curve point, cross point
  std::vector<transfinite::RibbonCurves> unit_curves_;  // the sides on [0, 1]
  std::shared_ptr<const transfinite::RibbonSet> ribbons_;
  Vec3 central_{0};
  double diameter_ = 1;
};

}  // namespace pl
