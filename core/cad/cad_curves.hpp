// The curves of a STEP or IGES file as free curves of a scene: every edge once (an edge that two
// faces share, once), its 3D curve over the edge's range as an exact B-spline or NURBS
// (OpenCASCADE's conversion, exact for lines, circles, conics, Bézier and B-spline curves),
// named as the file names the edge where OCCT's reader finds a name (STEP files PatchLab writes
// keep their curves' names on sub-shape labels that the reader does not bring back), else
// "<file stem> edge <i>". Degenerate edges (a cone's apex)
// and edges without a 3D curve are passed over (counted). This header includes no OCCT header.
#pragma once

#include <filesystem>
#include <vector>

#include "core/cad/cad_export.hpp"
#include "core/curve/scene_curve.hpp"

namespace pl {

struct CadCurves {
  std::vector<SceneCurve> curves;
  std::size_t passed_over = 0;
};

// Throws DataError naming the file: not a .step/.stp/.igs/.iges name, unreadable, OCCT's
// failures, reading past `time_limit_s` (<= 0: none), a file without an edge, a curve beyond the
// input limits.
CadCurves read_cad_curves(const std::filesystem::path& path,
                          double time_limit_s = kDefaultCadTimeLimit);

}  // namespace pl
