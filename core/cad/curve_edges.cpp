#include "core/cad/curve_edges.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <stdexcept>

namespace pl {

Handle(Geom_BSplineCurve) occt_curve(const SceneCurve& curve) {
  // Clamped: OCCT's non-periodic curves run over the whole knot vector's inner range with end
  // multiplicity degree + 1.
  const SplineCurve s = clamped(spline_form(curve));
  std::vector<double> values;
  std::vector<int> mults;
  for (double k : s.knots) {
    if (!values.empty() && values.back() == k) {
      ++mults.back();
      continue;
    }
    values.push_back(k);
    mults.push_back(1);
  }
  TColStd_Array1OfReal knots(1, static_cast<int>(values.size()));
  TColStd_Array1OfInteger multiplicities(1, static_cast<int>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, values[i]);
    multiplicities.SetValue(static_cast<int>(i) + 1, mults[i]);
  }
  TColgp_Array1OfPnt poles(1, static_cast<int>(s.points.size()));
  for (std::size_t i = 0; i < s.points.size(); ++i)
    poles.SetValue(static_cast<int>(i) + 1, gp_Pnt(s.points[i].x, s.points[i].y, s.points[i].z));
  if (!s.rational()) return new Geom_BSplineCurve(poles, knots, multiplicities, s.degree);
  TColStd_Array1OfReal weights(1, static_cast<int>(s.weights.size()));
  for (std::size_t i = 0; i < s.weights.size(); ++i)
    weights.SetValue(static_cast<int>(i) + 1, s.weights[i]);
  return new Geom_BSplineCurve(poles, weights, knots, multiplicities, s.degree);
}

TopoDS_Edge curve_edge(const SceneCurve& curve) {
  BRepBuilderAPI_MakeEdge make(occt_curve(curve));
  if (!make.IsDone()) throw std::runtime_error("OpenCASCADE could not make an edge of the curve");
  return make.Edge();
}

}  // namespace pl
