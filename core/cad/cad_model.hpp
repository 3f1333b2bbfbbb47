// The B-spline faces of an export: exact pieces as they are, fitted pieces fitted with their
// boundary rows pinned. Sides that coincide in space (a network edge between two faces, the seam
// between two pieces of one face, a Catmull-Clark edge) are found by sampling and get one curve:
// an exact one where any of the pieces knows it (a patch boundary, an exact neighbour's
// boundary row), else one fitted curve shared by all of them, so neighbours meet exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/cad/cad_pieces.hpp"

namespace pl {

struct CadFace {
  std::string name, owner;
  CadSurface surface;
  bool exact = false;
  // Fitted: largest deviation from the patch at the check grid (4x denser than the samples),
  // position and normal angle. Exact: the same measured on a 33 x 33 grid (rounding only).
  double position_deviation = 0, normal_deviation_deg = 0;
  int check_points = 0;  // per direction
  bool converged = true;
  FitEnd end = FitEnd::Converged;  // fitted: why the fit ended
  std::size_t work = 0;            // fitted: grid points of all its fits (spline_fit.hpp)
};

struct CadModel {
  double size = 0;       // diagonal of the scene's bounding box (sampled surfaces)
  double tolerance = 0;  // position tolerance of the fits
  double normal_tolerance_deg = 0.05;
  std::vector<CadPiece> pieces;
  std::vector<CadFace> faces;  // faces[i] is pieces[i]
  int exact_faces = 0, fitted_faces = 0;
  int shared_exact_sides = 0, shared_fitted_curves = 0;  // groups of coinciding sides
};

struct CadModelOptions {
  std::optional<double> tolerance;  // default: default_tolerance(size)
  double normal_tolerance_deg = 0.05;
  int max_spans = 64;
  // Per face, over all its fits (a face is fitted again when a curve it shares is tightened),
  // and per fitted side curve (spline_fit.hpp). A face that reaches it is not converged, with
  // end FitEnd::Work, and ends the tightening rounds.
  std::size_t max_work = kDefaultFitWork;
  std::size_t max_total_work = kDefaultExportWork;  // all fits of the export together
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

// Why a fit ended, in words ("its work bound of 2.1e+06 grid points reached").
std::string fit_end_text(FitEnd end, const FitTolerance& tol);

// The smaller of 1e-3 and 1e-5 of the bounding-box diagonal (scene units).
double default_tolerance(double diagonal);

// Diagonal of the bounding box of the pieces' surfaces, sampled on a 9 x 9 grid each.
double pieces_size(const std::vector<CadPiece>& pieces);

// Throws std::runtime_error naming the piece whose side curve could not be fitted (the fit's
// deviation, and the bound that stopped it); faces that do not converge are reported in
// CadFace::converged and ::end.
CadModel build_cad_model(std::vector<CadPiece> pieces, const CadModelOptions& options);

}  // namespace pl
