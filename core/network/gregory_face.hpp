// Gregory patches of 3- and 4-sided network faces, built from the faces' ribbons. Face side i
// becomes domain side i, traversed the same way with the same parameter.
#pragma once

#include <memory>

#include "core/network/face_ribbons.hpp"
#include "core/patch/patch.hpp"

namespace pl {

// Quadrilateral: boundary points are the edges' cubics; the twins of side i are its ribbon's
// inner[1], inner[2] (the bicubic second row: S_v = 3 (row 1 - row 0) on side 0).
// Triangular: boundaries are the cubics elevated to quartic; a quartic triangle's derivative
// towards the opposite corner on a side is 4 (row 1 - boundary), so the twins are
// boundary[j] + 3/4 (inner[j] - boundary[j]) and that derivative is the Chiyokura–Kimura field.
// Throws std::invalid_argument for other side counts.
std::unique_ptr<Patch> gregory_face_patch(const FaceRibbons& ribbons);

}  // namespace pl
