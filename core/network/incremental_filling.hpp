// The filling of a curve network kept up to date with its edits: the one place a network edit
// becomes new face patches. update() compares the edited network with the copy it last filled
// and recomputes only what depends on the difference:
//   - same structure (vertex, edge and face counts, edge ends and face loops unchanged; a drag,
//     a typed coordinate, a normal, a scheme): the tangent planes of the vertices whose position,
//     normal or end tangents changed, the Chiyokura–Kimura fields of the edges at those
//     vertices, and the faces using those edges. O(V + E) comparisons plus work local to the
//     edit: a drag frame costs the same on a network of 24 or of 1,536 faces.
//   - a new structure (vertices, edges or faces added, removed or re-connected, indices
//     renumbered): the network is validated again and its planes, fields and ribbons recomputed
//     (cheap, ~3 ms at 1,536 faces); a face whose ribbons and fill data equal those of a face
//     filled before keeps that face's patch, so only new or changed faces are built (a GB
//     patch costs ~0.1 ms to build) and evaluated.
//   - an interior edit (a GB face's offsets changed, nothing else: its ribbons, scheme and degree
//     are the same, and its patch is the interior form before and after, gb_face_interior.hpp): the
//     face is not refilled. Its patch differs from the one the caller holds only in the free points
//     whose offsets changed (GBInteriorPatch: the defaults depend on the ribbons alone), so it is
//     listed in interior_edited and the caller moves those points (SceneEvaluation: an axpy with
//     each point's influence column). A drag of a free point costs no patch build.
// A face's patch is a function of its resolved scheme, its ribbons (face_ribbons) and its degree
// and offsets, which is what makes that comparison exact.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/network/chiyokura_kimura.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/network_filling.hpp"
#include "core/network/tangent_planes.hpp"
#include "core/patch/gb/gb_interior_patch.hpp"

namespace pl {

struct FillingUpdate {
  // Faces were added, removed or renumbered: previous_face says where each face came from.
  bool renumbered = false;
  // Per current face: the face index before the update whose patch it keeps unchanged, or -1 when
  // it has a new patch. Without renumbering, face f keeps its own patch unless it is refilled.
  // Empty after update_interior(): every face keeps its own patch.
  std::vector<int> previous_face;
  // The faces with a new patch, ascending, with their patches (the caller's to keep).
  std::vector<FacePatch> refilled;
  // Faces whose name changed (nothing to evaluate).
  std::vector<int> renamed;
  // Faces whose offsets alone changed (see the header), ascending; they keep their patch
  // (previous_face[f] == f) and the caller moves its free points to the new offsets
  // (interior_point_moves).
  std::vector<int> interior_edited;
  bool projected_changed = false;  // projected_vertices() changed
};

// The moves that bring `patch` (a face's patch as last built or followed) to the offsets of
// `face`: (net index, new position) for every free point whose offset differs.
struct InteriorPointMove {
  std::size_t index;
  Vec3 position;
};
std::vector<InteriorPointMove> interior_point_moves(const GBInteriorPatch& patch,
                                                    const NetworkFace& face);

class IncrementalFilling {
 public:
  // The filling of an empty network: the first update() fills every face.
  IncrementalFilling(std::optional<FaceScheme> scheme_override, std::string source);

  // Follows `network`. Throws DataError (naming the source and the JSON path) when it cannot be
  // validated or filled; the filling is then left exactly as it was.
  FillingUpdate update(const Network& network);

  // The same when the caller knows that `network` differs from the filled copy at most in the
  // interior offsets of `faces` (a free-point drag step): a cost that follows those faces alone,
  // no scan of the network. The result lists the faces whose offsets differ in interior_edited
  // and leaves previous_face empty (every face keeps its patch); nothing is taken over yet: the
  // caller takes each listed face's offsets (exchange_offsets) as it follows that face. None when
  // the network does not bear the promise out (counts, or a listed face changed in more than its
  // offsets or in a way an interior edit cannot follow): then call update().
  std::optional<FillingUpdate> update_interior(const Network& network,
                                               std::span<const int> faces) const;
  // Gives face f these offsets, returning those it had (an interior edit taken over, or put back
  // when following it failed).
  std::vector<InteriorOffset> exchange_offsets(int face, std::vector<InteriorOffset> offsets);

  const Network& network() const { return network_; }
  const NetworkTopology& topology() const { return topology_; }
  const std::vector<TangentPlane>& planes() const { return planes_; }
  const std::vector<ProjectedVertex>& projected_vertices() const { return projected_; }
  const std::vector<int>& patch_side(int face) const { return faces_.at(face).patch_side; }
  // The face's patch built from scratch from the data last filled (what an interior edit
  // leaves the caller to follow point by point).
  FacePatch build(int face) const;

 private:
  struct Face {
    FaceScheme scheme = FaceScheme::Auto;  // resolved
    FaceRibbons ribbons;
    std::vector<int> patch_side;
    bool interior = false;  // its patch is a GBInteriorPatch
    bool centre = false;    // ... whose domain carries the central point
  };
  // The face data `f` as built into `face` (its patch side map and patch form).
  static void note_patch(Face& face, const FacePatch& fp);
  // Whether face f's change from the filled copy to `now` is an interior edit (header).
  bool interior_edit(int f, const Face& face, const NetworkFace& now) const;
  FillingUpdate update_in_place(const Network& network);
  FillingUpdate rebuild(const Network& network);
  bool same_structure(const Network& network) const;

  std::optional<FaceScheme> scheme_override_;
  std::string source_;
  Network network_;  // the network last filled
  NetworkTopology topology_;
  std::vector<TangentPlane> planes_;
  std::vector<EdgeCrossTangents> cross_;
  std::vector<Face> faces_;
  std::vector<ProjectedVertex> projected_;
};

}  // namespace pl
