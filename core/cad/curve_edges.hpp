// Free curves as OpenCASCADE edges on exact (rational) B-spline curves: the curve's clamped
// B-spline form (core/curve/spline_curve.hpp, exact knot insertion) with its knots, weights and
// poles as they are, so a CAD system reads the very curve of the scene.
//
// The scene format allows an interior knot of multiplicity degree + 1, where the curve breaks in
// two; OCCT's B-spline curves allow at most the degree inside (Standard_ConstructionError
// otherwise). Such a curve is exported as its pieces, one edge each.
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Edge.hxx>
#include <vector>

#include "core/curve/scene_curve.hpp"
#include "core/curve/spline_curve.hpp"

namespace pl {

// The clamped form cut at every interior knot of multiplicity degree + 1, in order; pieces
// whose points all coincide (no extent: nothing to draw) are left out.
std::vector<SplineCurve> curve_pieces(const SceneCurve& curve);

// A piece without interior breaks (as curve_pieces gives) as OCCT's curve.
Handle(Geom_BSplineCurve) occt_curve(const SplineCurve& piece);
// A curve without interior breaks; throws std::invalid_argument for a broken one.
Handle(Geom_BSplineCurve) occt_curve(const SceneCurve& curve);

// One edge per piece. Throws std::invalid_argument or OCCT's exceptions (callers go through
// occt_call, core/cad/occt_boundary.hpp).
std::vector<TopoDS_Edge> curve_edges(const SceneCurve& curve);

}  // namespace pl
