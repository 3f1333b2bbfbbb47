#include "core/cad/curve_edges.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <stdexcept>

#include "core/cad/cad_spline.hpp"

namespace pl {

namespace {

// Points [first, last) and the knots that go with them, as a curve of its own.
SplineCurve slice(const SplineCurve& s, std::size_t first, std::size_t last) {
  SplineCurve p;
  p.degree = s.degree;
  p.points.assign(s.points.begin() + first, s.points.begin() + last);
  if (s.rational()) p.weights.assign(s.weights.begin() + first, s.weights.begin() + last);
  p.knots.assign(s.knots.begin() + first, s.knots.begin() + last + s.degree + 1);
  return p;
}

bool has_extent(const SplineCurve& p) {
  for (const Vec3& q : p.points)
    if (q != p.points.front()) return true;
  return false;
}

}  // namespace

std::vector<SplineCurve> curve_pieces(const SceneCurve& curve) {
  // Clamped: OCCT's non-periodic curves run over the whole knot vector's inner range with end
  // multiplicity degree + 1.
  const SplineCurve s = clamped(spline_form(curve));
  const int p = s.degree;
  // With an interior knot value of multiplicity p + 1 at knots[k .. k + p], the curve left of it
  // uses points 0 .. k - 1 (knots 0 .. k + p), the curve right of it points k .. (knots k ..).
  std::vector<SplineCurve> pieces;
  std::size_t first = 0, k = p + 1;
  while (k < s.points.size()) {
    std::size_t m = 1;
    while (k + m < s.knots.size() && s.knots[k + m] == s.knots[k]) ++m;
    if (m == std::size_t(p) + 1 && k + m < s.knots.size()) {
      pieces.push_back(slice(s, first, k));
      first = k;
    }
    k += m;
  }
  pieces.push_back(slice(s, first, s.points.size()));
  std::erase_if(pieces, [](const SplineCurve& c) { return !has_extent(c); });
  return pieces;
}

Handle(Geom_BSplineCurve) occt_curve(const SplineCurve& s) {
  const auto runs = knot_runs(s.knots);
  TColStd_Array1OfReal knots(1, static_cast<int>(runs.size()));
  TColStd_Array1OfInteger multiplicities(1, static_cast<int>(runs.size()));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, runs[i].value);
    multiplicities.SetValue(static_cast<int>(i) + 1, runs[i].multiplicity);
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

Handle(Geom_BSplineCurve) occt_curve(const SceneCurve& curve) {
  const std::vector<SplineCurve> pieces = curve_pieces(curve);
  if (pieces.size() != 1)
    throw std::invalid_argument("the curve is broken into " + std::to_string(pieces.size()) +
                                " pieces");
  return occt_curve(pieces.front());
}

std::vector<TopoDS_Edge> curve_edges(const SceneCurve& curve) {
  std::vector<TopoDS_Edge> edges;
  for (const SplineCurve& piece : curve_pieces(curve)) {
    BRepBuilderAPI_MakeEdge make(occt_curve(piece));
    if (!make.IsDone())
      throw std::invalid_argument("OpenCASCADE could not make an edge of the curve");
    edges.push_back(make.Edge());
  }
  return edges;
}

}  // namespace pl
