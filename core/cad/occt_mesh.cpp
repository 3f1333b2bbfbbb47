#include "core/cad/occt_mesh.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

namespace pl {

std::vector<SurfaceMesh> occt_meshes(const TopoDS_Shape& shape, double deflection,
                                     double angular_deflection_rad) {
  BRepMesh_IncrementalMesh mesher(shape, deflection, false, angular_deflection_rad);
  std::vector<SurfaceMesh> out;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face face = TopoDS::Face(e.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) continue;
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const BRepAdaptor_Surface surface(face);
    SurfaceMesh m;
    m.name = "face" + std::to_string(out.size());
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(loc.Transformation());
      m.positions.emplace_back(p.X(), p.Y(), p.Z());
      Vec3 n(0, 0, 1);
      if (tri->HasUVNodes()) {
        const gp_Pnt2d uv = tri->UVNode(i);
        gp_Pnt q;
        gp_Vec du, dv;
        surface.D1(uv.X(), uv.Y(), q, du, dv);
        const gp_Vec c = du.Crossed(dv);
        if (c.Magnitude() > 0) n = Vec3(c.X(), c.Y(), c.Z()) / c.Magnitude();
      }
      m.normals.push_back(reversed ? -n : n);
    }
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int a, b, c;
      tri->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      m.triangles.push_back({uint32_t(a - 1), uint32_t(b - 1), uint32_t(c - 1)});
    }
    const std::size_t n = m.positions.size();
    m.gaussian.assign(n, 0.0), m.mean.assign(n, 0.0), m.kmin.assign(n, 0.0), m.kmax.assign(n, 0.0);
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<std::vector<Vec3>> occt_edge_polylines(const TopoDS_Shape& shape, int segments) {
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  std::vector<std::vector<Vec3>> out;
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(e)) continue;
    const BRepAdaptor_Curve c(e);
    std::vector<Vec3> line;
    for (int k = 0; k <= segments; ++k) {
      const double t = c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / segments;
      const gp_Pnt p = c.Value(t);
      line.emplace_back(p.X(), p.Y(), p.Z());
    }
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace pl
