// Shared pieces of the CAD tests: the scenes to export, the patch surface a piece stands for
// (evaluated here from the patch itself), and comparisons against surfaces read back by OCCT.
#pragma once

#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <filesystem>
#include <string>
#include <vector>

#include "core/cad/cad_pieces.hpp"
#include "core/cad/spline_fit.hpp"

namespace pl::test {

inline std::filesystem::path source_dir() {
  return PATCHLAB_SOURCE_DIR;
}

// Every sample scene of the repository (assets/ and assets/classic/).
inline std::vector<std::filesystem::path> asset_scenes() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : {"assets", "assets/classic"})
    for (const auto& e : std::filesystem::directory_iterator(source_dir() / dir))
      if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The GB reference models (.gbp) in the repository's test data; the list is empty (and the
// caller fails) when the folder is missing.
inline std::vector<std::filesystem::path> reference_models() {
  std::vector<std::filesystem::path> out;
  const auto dir = source_dir() / "tests/data/gb";
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".gbp") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The patch surface at piece parameter (u, v): the patch evaluated at the bilinear image of
// (u, v) in its domain, derivatives by the chain rule.
struct PieceTruth {
  Vec3 p, su, sv;
};
inline PieceTruth piece_truth(const CadPiece& piece, Vec2 uv) {
  const DomainQuad& q = piece.quad;
  const double u = uv.x, v = uv.y;
  const Vec2 x = (1 - u) * (1 - v) * q[0] + u * (1 - v) * q[1] + u * v * q[2] + (1 - u) * v * q[3];
  const Vec2 xu = (1 - v) * (q[1] - q[0]) + v * (q[2] - q[3]);
  const Vec2 xv = (1 - u) * (q[3] - q[0]) + u * (q[2] - q[1]);
  const SurfaceJet s = piece.patch->evaluate(x);
  return {s.p, xu.x * s.su + xu.y * s.sv, xv.x * s.su + xv.y * s.sv};
}

// Side s of a surface function as fit_surface numbers them (0: v = 0, 1: u = 1, 2: v = 1,
// 3: u = 0, each in increasing parameter): position and derivative along the side.
CurveFunction side_curve(const SurfaceFunction& f, int s);

// Largest deviation of an OCCT surface from a piece: position at equal parameters and the
// angle between normals (where the patch has one).
struct Deviation {
  double position = 0, normal_deg = 0;
  int points = 0;
};

// Parameters of `per_span` equal steps in every span between the distinct knots, and the end.
inline std::vector<double> per_span_params(const std::vector<double>& knots, int per_span) {
  std::vector<double> t;
  for (std::size_t k = 0; k + 1 < knots.size(); ++k)
    for (int j = 0; j < per_span; ++j)
      t.push_back(knots[k] + (knots[k + 1] - knots[k]) * (double(j) / per_span));
  t.push_back(knots.back());
  return t;
}

Deviation surface_deviation(const CadPiece& piece, const BRepAdaptor_Surface& s,
                            const std::vector<double>& tu, const std::vector<double>& tv);

// The check grid of a fitted face: four times the fit's samples per span (fit_samples_per_span)
// of the surface as read back (its own knots and degrees).
struct CheckGrid {
  std::vector<double> u, v;
};
CheckGrid fitted_check_grid(const BRepAdaptor_Surface& s);

}  // namespace pl::test
