// The polylines of a Wavefront OBJ file (`v x y z` vertices, `l i j k ...` lines) as free curves:
// each line a B-spline of degree 1 through its vertices, knots 0, 0, 1, ..., m - 1, m - 1 (one
// span per segment), named after the current `o`/`g` name and the line's number in the file.
// Faces, normals, texture coordinates and the rest are not curves: they are passed over (and
// counted). Indices are 1-based, negative ones count back from the last vertex read, `i/t` forms
// use the vertex index.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/curve/scene_curve.hpp"

namespace pl {

struct ObjCurves {
  std::vector<SceneCurve> curves;
  std::size_t faces_passed_over = 0;
};

// Throws DataError naming the file and the line: unreadable, larger than the input limit, a
// malformed vertex or line, an index out of range, a coordinate beyond the input limit, a line
// of fewer than two points or with two equal consecutive points, or no line at all.
ObjCurves read_obj_curves(const std::filesystem::path& path);

}  // namespace pl
