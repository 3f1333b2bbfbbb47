// The GUI-free entry point of the STEP/IGES export: a scene in, a file out, a report back.
// Includes no OpenCASCADE header, so callers (the CLI, the editor) need only link patchlab_cad.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

enum class CadFormat { Step, Iges };

// The CAD format of a file name: .step, .stp (STEP AP242), .igs, .iges (IGES), any letter case;
// nullopt for anything else.
std::optional<CadFormat> cad_format_for(const std::filesystem::path& path);

// The bounds of a STEP/IGES export (docs/limits.md), checked before the work they bound.
// Size: the diagonal of the bounding box of the scene's control points, in scene units
// (millimetres in the file). OpenCASCADE's distances are absolute: Precision::Confusion() =
// 1e-7 is the smallest it tells apart and 2e100 its infinity, and its sewing, face and edge
// tolerances follow the scene's size. Within this range a file reads back with its gaps at
// rounding; outside it the export is refused, saying so.
inline constexpr double kMinCadSize = 1e-3;
inline constexpr double kMaxCadSize = 1e9;
// Faces (four-sided pieces) of one export: the sewing, the fits and the file grow with them.
inline constexpr std::size_t kMaxCadFaces = 16384;
// The wall-clock limit of one export (the fits, the sewing, the translation), a last resort
// behind the work bounds: an export that reaches it stops with a message.
inline constexpr double kDefaultCadTimeLimit = 120;

struct CadExportOptions {
  std::optional<double> tolerance;             // default: min(1e-3, 1e-5 x bounding-box diagonal)
  std::optional<FaceScheme> scheme;            // how network faces are filled (as `--scheme`)
  std::string source;                          // the scene's file, for messages
  double time_limit_s = kDefaultCadTimeLimit;  // <= 0: none
  std::size_t max_fit_work = 0;                // per fit, in grid points; 0: the default
};

// The diagonal of the bounding box of the scene's control points: network vertices and
// handles, patches' control points, free curves' (spline form's) points.
double scene_control_size(const Scene& scene);

struct CadFaceReport {
  std::string name;
  bool exact = false;
  double position_deviation = 0;  // scene units, at the check grid
  double normal_deviation_deg = 0;
  int check_points = 0;  // per direction
  std::size_t control_points = 0;
  int degree_u = 0, degree_v = 0;
};

struct CadExportReport {
  CadFormat format = CadFormat::Step;
  std::filesystem::path target;
  double size = 0, tolerance = 0, normal_tolerance_deg = 0.05;
  std::vector<CadFaceReport> faces;
  int curves = 0;         // free curves, written as exact (rational) B-spline edges
  int broken_curves = 0;  // of them, broken at a knot of multiplicity degree + 1 (into pieces)
  int curve_edges = 0;    // the edges written for the curves
  int exact_faces = 0, fitted_faces = 0;
  // The sewn shape, as written.
  int shells = 0, closed_shells = 0, solids = 0;
  int free_edges = 0, sewn_edges = 0, multiple_edges = 0;
  double max_gap = 0, max_normal_angle_deg = 0;
  double sewing_tolerance = 0;
};

// Builds the faces (exact or fitted), sews them, writes `target` atomically and reports.
// Throws DataError (source, where, message) for data it cannot export (a size outside
// [kMinCadSize, kMaxCadSize], more than kMaxCadFaces faces), a fit that does not reach the
// tolerance within its bounds (naming the face and the bound), the time limit, a failure of
// OpenCASCADE (naming the face or curve and OCCT's reason), or a file it cannot write (then
// naming the target and the reason; the target is left as it was). Nothing else escapes.
CadExportReport export_cad(const Scene& scene, const std::filesystem::path& target,
                           const CadExportOptions& options);

// Human-readable: one line per face, then the shell.
std::string cad_report_text(const CadExportReport& report);

}  // namespace pl
