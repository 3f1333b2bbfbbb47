// Fills the faces of a validated curve network with patches (Gregory or GB) whose
// cross-boundary tangents come from the Chiyokura–Kimura construction.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/network/tangent_planes.hpp"
#include "core/patch/patch.hpp"
#include "core/scene/network.hpp"

namespace pl {

struct FacePatch {
  int face = -1;
  std::shared_ptr<Patch> patch;
  // patch_side[i]: the patch domain side that carries face side i, traversed in the same
  // direction (from loop[i] to loop[i+1]) with side parameter = edge curve parameter.
  std::vector<int> patch_side;
};

struct NetworkFilling {
  std::vector<FacePatch> faces;
  std::vector<ProjectedVertex> projected_vertices;
};

struct FaceRibbons;

// The patch of one face with the given (resolved) scheme from its ribbons: the one place a face
// becomes a patch, shared by fill_network and the network editor. Throws DataError naming
// "network.faces[face]" for faces it cannot fill.
// `data` is the face itself: a GB face takes its degree and offsets from it.
FacePatch build_face_patch(int face, FaceScheme scheme, const FaceRibbons& ribbons,
                           const NetworkFace& data, const std::string& source);

// Checks that the faces near `vertices` can be filled: the tangent planes at those vertices and
// at the other ends of their edges, the fields of those edges and the patches of the faces using
// them are built (and dropped). What an edit near those vertices needs to know before it is made,
// at a cost local to them. Throws DataError (source, JSON path, ...) like fill_network.
void check_fillable_near(const Network& network, const NetworkTopology& topology,
                         std::span<const int> vertices, const std::string& source);

// Throws DataError (source, "network.faces[i]", ...) for geometry it cannot fill.
NetworkFilling fill_network(const Network& network, const NetworkTopology& topology,
                            std::optional<FaceScheme> scheme_override, const std::string& source);

}  // namespace pl
