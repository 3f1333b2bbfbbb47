// The names of a scene's surfaces, as every output lists them (figures, meshes, CAD faces, the
// editor's lists): a network face or scene patch by its own name, or face<i> / patch<i> without
// one; a patch split into several pieces names piece k <name>.<k>.
#pragma once

#include <cstddef>
#include <string>

#include "core/scene/scene.hpp"

namespace pl {

std::string face_surface_name(const Network& network, int face);
std::string patch_surface_name(const Scene& scene, std::size_t patch);
// Piece k of `pieces` of a surface named `owner`: the owner itself when it is one piece.
std::string piece_name(const std::string& owner, std::size_t pieces, std::size_t k);

}  // namespace pl
