// Free curves as OpenCASCADE edges on exact (rational) B-spline curves: the curve's clamped
// B-spline form (core/curve/spline_curve.hpp, exact knot insertion) with its knots, weights and
// poles as they are, so a CAD system reads the very curve of the scene.
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Edge.hxx>

#include "core/curve/scene_curve.hpp"

namespace pl {

Handle(Geom_BSplineCurve) occt_curve(const SceneCurve& curve);
TopoDS_Edge curve_edge(const SceneCurve& curve);

}  // namespace pl
