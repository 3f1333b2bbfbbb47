// Writes tessellated surfaces as OBJ, PLY (with per-vertex curvature), OFF or STL, atomically.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/polyline.hpp"
#include "core/mesh/surface_mesh.hpp"

namespace pl {

enum class MeshFormat { Obj, Ply, Off, Stl };

// From the file extension; throws DataError for an unknown one.
MeshFormat mesh_format_for(const std::filesystem::path& path);
// The same, nullopt for a name that is none of them.
std::optional<MeshFormat> find_mesh_format(const std::filesystem::path& path);

// Throws DataError on failure; the previous file is left intact. Every sample is checked first
// (check_finite): a bad one is reported with `source` (the input file; the target if empty), the
// patch and the domain parameter, and nothing is written. Polylines (free curves) go to OBJ
// only, after the patches; the other formats leave them out.
void export_meshes(const std::vector<SurfaceMesh>& meshes, const std::filesystem::path& path,
                   const std::string& source = "",
                   const std::vector<CurvePolyline>& polylines = {});

}  // namespace pl
