// A shape's faces tessellated by OpenCASCADE (BRepMesh), as PatchLab's plain surface arrays, so
// that a file read back can be drawn by PatchLab's renderer next to PatchLab's own tessellation.
// Includes OCCT.
#pragma once

#include <TopoDS_Shape.hxx>
#include <vector>

#include "core/mesh/surface_mesh.hpp"

namespace pl {

// One mesh per face; normals are the face's surface normals at the mesh nodes (outward, as the
// face is oriented), curvature arrays are zero. deflection: BRepMesh's linear deflection.
std::vector<SurfaceMesh> occt_meshes(const TopoDS_Shape& shape, double deflection,
                                     double angular_deflection_rad = 0.1);

// Every edge of the shape (once, degenerate edges aside) as a polyline of `segments` segments.
std::vector<std::vector<Vec3>> occt_edge_polylines(const TopoDS_Shape& shape, int segments = 32);

}  // namespace pl
