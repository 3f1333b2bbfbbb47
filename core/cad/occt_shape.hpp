// OpenCASCADE side of the export (this header includes OCCT; only core/cad sources and the CAD
// tests include it): B-spline faces, sewing into shells (closed shells become solids), and the
// measurements of a sewn shape that the export reports and the tests check on files read back.
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <vector>

#include "core/cad/cad_model.hpp"
#include "core/cad/occt_boundary.hpp"

namespace pl {

Handle(Geom_BSplineSurface) occt_surface(const CadSurface& s);

struct SewnShape {
  TopoDS_Shape shape;              // a solid, a shell, or a compound of them
  std::vector<TopoDS_Face> faces;  // faces[i]: the sewn face of model.faces[i]
  int shells = 0, closed_shells = 0, solids = 0;
};

// Sews the model's faces with the given tolerance (merging edges closer than it); every closed
// shell becomes a solid, oriented so that its faces' normals point out of it. Throws DataError
// (source, the face, the reason) where OCCT fails, and once the deadline passes.
SewnShape sew_model(const CadModel& model, double tolerance, const std::string& source = "",
                    const CadDeadline& deadline = CadDeadline());

// What the sewing achieved, measured on any shape (a sewn model, or a file read back):
//   free edges: edges used by one face only (seams of closed faces and degenerate edges aside);
//   sewn edges: edges shared by two faces; for each, at `samples` points along it, the gap
//   (distance from the first face's boundary point to the second face, found by projection
//   onto the second face's surface) and the angle between the two faces' outward normals there.
struct ShellReport {
  int faces = 0, shells = 0, closed_shells = 0, solids = 0;
  int free_edges = 0, sewn_edges = 0, multiple_edges = 0;  // multiple: more than two faces
  double max_gap = 0;                                      // scene units
  double max_normal_angle_deg = 0;
};
ShellReport analyze_shell(const TopoDS_Shape& shape, int samples = 9);

}  // namespace pl
