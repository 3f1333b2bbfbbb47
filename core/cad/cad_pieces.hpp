// The four-sided pieces a scene is exported as: one STEP/IGES face each. A piece is a convex
// quadrilateral of one patch's domain, mapped bilinearly from the unit square; it is either
// exact (its B-spline form is the patch itself) or fitted (cad_model.hpp fits it).
//
//   exact:  bezier, bspline, nurbs, hermite, interpolating, coons-network, pair-join (one piece
//           each); the q and r parts of a gap-fill; Catmull-Clark faces whose limit surface is a
//           bicubic polynomial (regular faces: detected by reproducing the face from 16 samples
//           and checking it at 81 others).
//   fitted: Gregory quadrilaterals (one piece), triangular Gregory and GB faces (split by
//           domain_quads.hpp), the fill of a gap-fill, irregular Catmull-Clark faces, and any
//           other type.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/cad/cad_spline.hpp"
#include "core/cad/domain_quads.hpp"
#include "core/cad/spline_fit.hpp"
#include "core/scene/scene.hpp"

namespace pl {

struct CadPiece {
  std::string name;   // the face name written to the file: the owner, or owner.k for parts
  std::string owner;  // the scene surface: network face or scene patch name
  std::shared_ptr<const Patch> patch;
  DomainQuad quad;                  // piece (u, v) -> patch domain
  std::optional<CadSurface> exact;  // the exact form, for exact pieces
  // Fitted pieces: the exact curves of sides that lie on the patch's boundary (sides as in
  // fit_surface: 0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0, each in increasing parameter); the
  // others are shared with a neighbour or fitted (cad_model.hpp).
  std::array<std::optional<CadCurve>, 4> known_sides;
  int degree = 3;  // degree of curves fitted for this piece's other sides
};

// Every piece of the scene, network faces first (filled with the scheme, as evaluate_scene
// does), then the scene's patches. Throws DataError naming `source` and the face or patch.
std::vector<CadPiece> cad_pieces(const Scene& scene, std::optional<FaceScheme> scheme,
                                 const std::string& source);

// The piece's surface S(patch domain point of (u, v)) with derivatives in (u, v).
SurfaceFunction piece_function(const CadPiece& piece);

}  // namespace pl
