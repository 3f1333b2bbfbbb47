// Exact B-spline forms of the patch types that are polynomial or rational tensor-product
// surfaces. "Exact" means the same surface over the same parameters: S_cad(u, v) equals
// patch.evaluate({u, v}) up to rounding for every (u, v) in [0, 1]^2.
#pragma once

#include <functional>
#include <optional>

#include "core/cad/cad_spline.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/nurbs_patch.hpp"
#include "core/patch/surface_jet.hpp"

namespace pl {

CadSurface bezier_surface(const BezierPatch& patch);
// The patch's knots clamped at both ends of its range (Boehm insertion, homogeneous points for
// NURBS) and mapped affinely onto [0, 1]: the patch domain maps onto the knot range the same way.
CadSurface bspline_surface(const BSplinePatch& patch);
CadSurface nurbs_surface(const NurbsPatch& patch);

// The Bézier patch of bidegree (m, n) that interpolates f at the tensor grid (a/m, b/n): the
// polynomial itself when f is a polynomial of at most that bidegree (a unisolvent problem,
// solved with Eigen; degrees <= 7 keep the system well conditioned).
BezierPatch interpolate_polynomial(int m, int n, const std::function<Vec3(Vec2)>& f);

// Bézier cells of equal size (cells_u x cells_v, cell (a, b) = cells[a * cells_v + b], all of
// the same bidegree) joined into one B-spline surface with C0 knots at the cell breaks; shared
// boundary rows are taken from the lower-index cell.
CadSurface join_bezier_cells(int cells_u, int cells_v, const std::vector<BezierPatch>& cells);

// The exact form of any patch whose type is a polynomial or rational tensor-product surface
// over its whole domain (bezier, bspline, nurbs, hermite, interpolating, coons-network,
// pair-join); nullopt for every other registered type (one overload per type in the .cpp).
// Catmull-Clark faces and gap-fill pieces are decided by the piece builder (cad_pieces.hpp).
std::optional<CadSurface> exact_surface(const Patch& patch);

}  // namespace pl
