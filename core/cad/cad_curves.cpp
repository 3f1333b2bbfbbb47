#include "core/cad/cad_curves.hpp"

#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopLoc_Location.hxx>
#include <cmath>

#include "core/base/data_error.hpp"
#include "core/cad/occt_io.hpp"
#include "core/io/input_limits.hpp"

namespace pl {

namespace {

SceneCurve scene_curve_of(Handle(Geom_BSplineCurve) b) {
  if (b->IsPeriodic()) {  // the same curve with a clamped knot vector
    b = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
    b->SetNotPeriodic();
  }
  SceneCurve c;
  c.type = b->IsRational() ? CurveType::Nurbs : CurveType::BSpline;
  c.degree = b->Degree();
  for (int i = 1; i <= b->NbPoles(); ++i) {
    const gp_Pnt p = b->Pole(i);
    c.points.emplace_back(p.X(), p.Y(), p.Z());
    if (b->IsRational()) c.weights.push_back(b->Weight(i));
  }
  TColStd_Array1OfReal knots(1, b->NbPoles() + b->Degree() + 1);
  b->KnotSequence(knots);
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) c.knots.push_back(knots(i));
  return c;
}

}  // namespace

CadCurves read_cad_curves(const std::filesystem::path& path, double time_limit_s) {
  const std::string file = path.string();
  const auto format = cad_format_for(path);
  if (!format) throw DataError(file, "", "not a STEP (.step, .stp) or IGES (.igs, .iges) file");
  const CadFile cad = read_cad_file(path, *format, CadDeadline(time_limit_s));
  CadCurves out;
  for (std::size_t i = 0; i < cad.edges.size(); ++i) {
    const auto& [name, edge] = cad.edges[i];
    const std::string label =
        name.empty() ? path.stem().string() + " edge " + std::to_string(i) : name;
    const CadPlace place{file, label};
    SceneCurve c = occt_call(place, "cannot take the edge's curve", [&, &edge = edge] {
      SceneCurve none;
      if (BRep_Tool::Degenerated(edge)) return none;
      TopLoc_Location where;
      double first = 0, last = 0;
      Handle(Geom_Curve) g = BRep_Tool::Curve(edge, where, first, last);
      if (g.IsNull() || !(last > first)) return none;
      if (!where.IsIdentity())
        g = Handle(Geom_Curve)::DownCast(g->Transformed(where.Transformation()));
      const Handle(Geom_TrimmedCurve) piece = new Geom_TrimmedCurve(g, first, last);
      return scene_curve_of(GeomConvert::CurveToBSplineCurve(piece));
    });
    if (c.points.empty()) {
      ++out.passed_over;
      continue;
    }
    for (const Vec3& p : c.points)
      if (!(std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
            std::fabs(p.z) <= kMaxCoordinate))
        throw DataError(file, label, "a control point is beyond the input limit");
    try {
      validate_curve(c);
    } catch (const std::invalid_argument& e) {
      throw DataError(file, label, e.what());
    }
    c.name = label;
    out.curves.push_back(std::move(c));
  }
  if (out.curves.empty()) throw DataError(file, "", "no edge with a curve in the file");
  return out;
}

}  // namespace pl
