// Exact Catmull-Clark limit surface of a polygon control mesh, evaluated with OpenSubdiv
// (Far::TopologyRefiner adaptive refinement, Far::PatchTable + Far::PatchMap, Gregory end caps at
// extraordinary vertices). The control mesh topology is held in an OpenMesh polygon mesh, which
// also validates it (manifold, consistently oriented). Weights are expressed over the base
// control vertices, so the surface is linear in them (the Patch contract).
//
// Face parameterisation (OpenSubdiv's ptex faces): a quad f = (v0, v1, v2, v3) is one ptex face,
// u runs v0 -> v1, v from v0 -> v3, so S_u x S_v points to the side from which the loop is
// counter-clockwise. A face with n != 4 vertices is n ptex faces (its quadrangulation: sub-face
// k is the quad at corner k, from v_k to the face centre), numbered consecutively in face order.
//
// Cost. The limit patches are built on *patch points* (refined vertices and end-cap points),
// each a stencil over the base vertices. Near an n-sided face or an n-valent vertex every patch
// point depends on all n vertices of the ring, so summing stencils per sample costs O(n) per
// sample; instead a face's patch points are placed once (local_points) and each sample sums the
// 16 or 20 points of its patch: O(1) per sample, whatever n.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

class CatmullClarkLimit {
 public:
  // At most kMaxValence vertices in a face and faces around a vertex: the patch points near such
  // a face or vertex each hold the whole ring, so building them costs O(n^2) memory and at least
  // as much time (a 10,000-sided face would take gigabytes; build_stencils says how the time is
  // kept near that). At most kMaxVertices vertices.
  static constexpr int kMaxValence = 256;
  static constexpr std::size_t kMaxVertices = std::size_t(1) << 16;

  // Throws std::invalid_argument: a face with fewer than 3 vertices or a repeated vertex, vertex
  // index out of range, an edge used twice in one direction (flipped or non-manifold faces),
  // non-manifold vertices, unused vertices, and meshes beyond kMaxValence or kMaxVertices.
  CatmullClarkLimit(std::size_t vertex_count, const std::vector<std::vector<int>>& faces);
  ~CatmullClarkLimit();
  CatmullClarkLimit(const CatmullClarkLimit&) = delete;
  CatmullClarkLimit& operator=(const CatmullClarkLimit&) = delete;

  std::size_t vertex_count() const { return vertex_count_; }
  std::size_t face_count() const { return faces_.size(); }
  const std::vector<std::vector<int>>& faces() const { return faces_; }
  bool boundary_vertex(int v) const;
  // Ptex faces (one per quad, n per n-gon) and the base face each belongs to.
  std::size_t ptex_count() const { return ptex_face_.size(); }
  int ptex_face(int ptex) const { return ptex_face_.at(ptex); }

  // The non-zero limit basis functions of ptex face `ptex` at (u, v) in [0,1]^2:
  // (base vertex, jet), ascending by vertex. O(n) for a face next to an n-valent vertex.
  std::vector<std::pair<int, Jet>> basis(int ptex, Vec2 uv) const;

  // The patch points ptex face `ptex` is built on (indices of the patch table's points,
  // ascending), and the stencil of one patch point over the base vertices (ascending vertices).
  const std::vector<int>& face_points(int ptex) const { return face_points_.at(ptex); }
  std::span<const int> stencil_vertices(int point) const;
  std::span<const double> stencil_weights(int point) const;
  // A patch point's position for these base vertex positions, relative to its heaviest vertex
  // (exactly that vertex where only coinciding vertices carry weight).
  Vec3 patch_point(int point, std::span<const Vec3> vertices) const;

  // The limit patch at (u, v) of ptex face `ptex`: its points as indices into face_points(ptex)
  // and their basis jets (derivatives with respect to the ptex face's own (u, v)).
  struct LocalBasis {
    int count = 0;
    std::array<int, 20> point;
    std::array<Jet, 20> weight;
  };
  LocalBasis local_basis(int ptex, Vec2 uv) const;

  // The limit point of ptex face `ptex` at (u, v) for these vertex positions through OpenSubdiv's
  // limit stencils (Far::LimitStencilTableFactory: its own patch lookup, basis evaluation and
  // stencil accumulation), a path independent of basis(): used for boundary deviation. Slower than
  // basis() (a stencil table per call).
  Vec3 limit_point(int ptex, Vec2 uv, const std::vector<Vec3>& points) const;

  // The same limit point summed over the base vertices: the patch's basis (found through the
  // patch map built once) times its patch points' stencils, O(m) for the m stencil entries of
  // that patch. limit_point builds a patch map over the whole patch table and merges stencils by
  // linear search on every call: O(patches + m^2), which made the boundary samples of `analyze`
  // on a 256-gon or a valence-200 fan take tens of seconds. The boundary points of the patches
  // (Patch::boundary_point) come from here; limit_point stays as the independent reference of
  // the tests.
  Vec3 stencil_point(int ptex, Vec2 uv, std::span<const Vec3> points) const;

 private:
  void build_stencils();
  struct Osd;
  std::size_t vertex_count_;
  std::vector<std::vector<int>> faces_;
  std::vector<int> ptex_face_;
  std::vector<std::vector<int>> face_points_;  // [ptex]: patch points, ascending
  // [patch]: offset into patch_local_ of its points as indices into its face's face_points.
  std::vector<int> patch_local_offset_;
  std::vector<int> patch_local_;
  std::unique_ptr<Osd> osd_;
};

}  // namespace pl
