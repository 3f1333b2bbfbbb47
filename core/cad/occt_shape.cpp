#include "core/cad/occt_shape.hpp"

#include <BRepAdaptor_Curve2d.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pl {

namespace {

void knots_and_mults(const std::vector<double>& U, TColStd_Array1OfReal& k,
                     TColStd_Array1OfInteger& m) {
  const auto runs = knot_runs(U);
  k.Resize(1, static_cast<int>(runs.size()), false);
  m.Resize(1, static_cast<int>(runs.size()), false);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    k(static_cast<int>(r) + 1) = runs[r].value;
    m(static_cast<int>(r) + 1) = runs[r].multiplicity;
  }
}

// Outward normal of a face at (u, v): the surface normal, flipped for reversed faces.
bool face_normal(const BRepAdaptor_Surface& s, const TopoDS_Face& f, double u, double v,
                 gp_Vec& n) {
  gp_Pnt p;
  gp_Vec du, dv;
  s.D1(u, v, p, du, dv);
  n = du.Crossed(dv);
  if (n.Magnitude() < 1e-300) return false;
  if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
  return true;
}

}  // namespace

Handle(Geom_BSplineSurface) occt_surface(const CadSurface& s) {
  validate_cad_surface(s);
  TColgp_Array2OfPnt poles(1, static_cast<int>(s.nu), 1, static_cast<int>(s.nv));
  for (std::size_t i = 0; i < s.nu; ++i)
    for (std::size_t j = 0; j < s.nv; ++j) {
      const Vec3& p = s.at(i, j);
      poles(static_cast<int>(i) + 1, static_cast<int>(j) + 1) = gp_Pnt(p.x, p.y, p.z);
    }
  TColStd_Array1OfReal ku(1, 1), kv(1, 1);
  TColStd_Array1OfInteger mu(1, 1), mv(1, 1);
  knots_and_mults(s.knots_u, ku, mu);
  knots_and_mults(s.knots_v, kv, mv);
  if (!s.rational()) return new Geom_BSplineSurface(poles, ku, kv, mu, mv, s.degree_u, s.degree_v);
  TColStd_Array2OfReal w(1, static_cast<int>(s.nu), 1, static_cast<int>(s.nv));
  for (std::size_t i = 0; i < s.nu; ++i)
    for (std::size_t j = 0; j < s.nv; ++j)
      w(static_cast<int>(i) + 1, static_cast<int>(j) + 1) = s.weights[i * s.nv + j];
  return new Geom_BSplineSurface(poles, w, ku, kv, mu, mv, s.degree_u, s.degree_v);
}

SewnShape sew_model(const CadModel& model, double tolerance, const std::string& source,
                    const CadDeadline& deadline) {
  std::vector<TopoDS_Face> made;
  BRepBuilderAPI_Sewing sewing(tolerance);
  for (const CadFace& f : model.faces) {
    made.push_back(occt_call({source, f.name}, "OpenCASCADE cannot make a face of it", [&] {
      BRepBuilderAPI_MakeFace mf(occt_surface(f.surface), Precision::Confusion());
      if (!mf.IsDone()) throw std::runtime_error("BRepBuilderAPI_MakeFace failed");
      return mf.Face();
    }));
    sewing.Add(made.back());
  }
  const Handle(Message_ProgressIndicator) progress = deadline.indicator();
  occt_call_until({source, ""}, "sewing the faces", deadline,
                  [&] { sewing.Perform(progress->Start()); });
  SewnShape out;
  const TopoDS_Shape sewn = sewing.SewedShape();
  // Closed shells become solids; open shells and lone faces stay as they are.
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  int parts = 0;
  TopoDS_Shape single;
  for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) {
    TopoDS_Shell shell = TopoDS::Shell(e.Current());
    ++out.shells;
    TopoDS_Shape part = shell;
    if (BRep_Tool::IsClosed(shell)) {
      ++out.closed_shells;
      BRepBuilderAPI_MakeSolid ms(shell);
      if (ms.IsDone()) {
        TopoDS_Solid solid = ms.Solid();
        BRepClass3d_SolidClassifier inside(solid);
        inside.PerformInfinitePoint(Precision::Confusion());
        if (inside.State() == TopAbs_IN) solid.Reverse();
        part = solid;
        ++out.solids;
      }
    }
    builder.Add(all, part);
    single = part;
    ++parts;
  }
  // A face the sewing left outside every shell gets a shell of its own: the file then has a
  // shape (named after the scene) whose faces carry their own names.
  for (TopExp_Explorer e(sewn, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) {
    TopoDS_Shell shell;
    builder.MakeShell(shell);
    builder.Add(shell, e.Current());
    builder.Add(all, shell);
    single = shell;
    ++out.shells;
    ++parts;
  }
  out.shape = parts == 1 ? single : TopoDS_Shape(all);
  // The sewn face of each model face (sewing replaces faces whose edges it merged), located in
  // the final shape so that names attach to it.
  TopTools_IndexedMapOfShape in_shape;
  TopExp::MapShapes(out.shape, TopAbs_FACE, in_shape);
  for (const TopoDS_Face& f : made) {
    TopoDS_Shape s = sewing.IsModified(f) ? sewing.Modified(f) : TopoDS_Shape(f);
    // (A face the sewing dropped is a null shape, whose type must not be asked: SIGSEGV.)
    if (!s.IsNull() && s.ShapeType() != TopAbs_FACE) {  // a face the sewing split: its first part
      TopExp_Explorer e(s, TopAbs_FACE);
      s = e.More() ? e.Current() : TopoDS_Shape();
    }
    const int k = s.IsNull() ? 0 : in_shape.FindIndex(s);
    out.faces.push_back(k > 0 ? TopoDS::Face(in_shape(k)) : TopoDS_Face());
  }
  return out;
}

ShellReport analyze_shell(const TopoDS_Shape& shape, int samples) {
  ShellReport r;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++r.faces;
  for (TopExp_Explorer e(shape, TopAbs_SHELL); e.More(); e.Next()) {
    ++r.shells;
    if (BRep_Tool::IsClosed(TopoDS::Shell(e.Current()))) ++r.closed_shells;
  }
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++r.solids;
  TopTools_IndexedDataMapOfShapeListOfShape faces_of;
  TopExp::MapShapesAndUniqueAncestors(shape, TopAbs_EDGE, TopAbs_FACE, faces_of);
  for (int i = 1; i <= faces_of.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(faces_of.FindKey(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    const TopTools_ListOfShape& faces = faces_of(i);
    if (faces.Extent() == 1) {
      if (!BRep_Tool::IsClosed(edge, TopoDS::Face(faces.First()))) ++r.free_edges;
      continue;
    }
    if (faces.Extent() > 2) {
      ++r.multiple_edges;
      continue;
    }
    ++r.sewn_edges;
    const TopoDS_Face fa = TopoDS::Face(faces.First()), fb = TopoDS::Face(faces.Last());
    const BRepAdaptor_Curve2d ca(edge, fa), cb(edge, fb);
    const BRepAdaptor_Surface sa(fa), sb(fb);
    Handle(ShapeAnalysis_Surface) project = new ShapeAnalysis_Surface(BRep_Tool::Surface(fb));
    const double t0 = ca.FirstParameter(), t1 = ca.LastParameter();
    for (int k = 0; k <= samples; ++k) {
      const double t = t0 + (t1 - t0) * k / samples;
      const gp_Pnt2d uva = ca.Value(t);
      const gp_Pnt pa = sa.Value(uva.X(), uva.Y());
      // Start the projection from the second face's own curve on the edge.
      const gp_Pnt2d guess = cb.Value(t);
      const gp_Pnt2d uvb = project->NextValueOfUV(guess, pa, Precision::Confusion());
      const gp_Pnt pb = sb.Value(uvb.X(), uvb.Y());
      r.max_gap = std::max(r.max_gap, pa.Distance(pb));
      gp_Vec na, nb;
      if (face_normal(sa, fa, uva.X(), uva.Y(), na) && face_normal(sb, fb, uvb.X(), uvb.Y(), nb))
        r.max_normal_angle_deg =
            std::max(r.max_normal_angle_deg, na.Angle(nb) * 180.0 / std::numbers::pi);
    }
  }
  return r;
}

}  // namespace pl
