// The GUI-free entry point of the STEP/IGES export: a scene in, a file out, a report back.
// Includes no OpenCASCADE header, so callers (the CLI, the editor) need only link patchlab_cad.
#pragma once

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

struct CadExportOptions {
  std::optional<double> tolerance;   // default: min(1e-3, 1e-5 x bounding-box diagonal)
  std::optional<FaceScheme> scheme;  // how network faces are filled (as `--scheme`)
  std::string source;                // the scene's file, for messages
};

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
  int curves = 0;  // free curves, written as exact (rational) B-spline edges
  int exact_faces = 0, fitted_faces = 0;
  // The sewn shape, as written.
  int shells = 0, closed_shells = 0, solids = 0;
  int free_edges = 0, sewn_edges = 0, multiple_edges = 0;
  double max_gap = 0, max_normal_angle_deg = 0;
  double sewing_tolerance = 0;
};

// Builds the faces (exact or fitted), sews them, writes `target` atomically and reports.
// Throws DataError (source, where, message) for data it cannot export, a fit that does not reach
// the tolerance, or a file it cannot write (then naming the target and the reason; the target is
// left as it was).
CadExportReport export_cad(const Scene& scene, const std::filesystem::path& target,
                           const CadExportOptions& options);

// Human-readable: one line per face, then the shell.
std::string cad_report_text(const CadExportReport& report);

}  // namespace pl
