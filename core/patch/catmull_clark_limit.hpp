// Exact Catmull-Clark limit surface of a quad control mesh, evaluated with OpenSubdiv
// (Far::TopologyRefiner adaptive refinement, Far::PatchTable + Far::PatchMap, Gregory end caps at
// extraordinary vertices). The control mesh topology is held in an OpenMesh polygon mesh, which
// also validates it (manifold, consistently oriented). Weights are expressed over the base
// control vertices, so the surface is linear in them (the Patch contract).
//
// Face parameterisation (OpenSubdiv's ptex faces): a quad f = (v0, v1, v2, v3) is one ptex face,
// u runs v0 -> v1, v from v0 -> v3, so S_u x S_v points to the side from which the loop is
// counter-clockwise. A face with n != 4 vertices is n ptex faces (its quadrangulation: sub-face
// k is the quad at corner k, from v_k to the face centre), numbered consecutively in face order.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl {

class CatmullClarkLimit {
 public:
  // Throws std::invalid_argument: a face with fewer than 3 vertices, vertex index out of range,
  // non-manifold or inconsistently oriented faces, unused vertices.
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
  // (base vertex, jet).
  std::vector<std::pair<int, Jet>> basis(int ptex, Vec2 uv) const;

  // The limit point of ptex face `ptex` at (u, v) for these vertex positions through OpenSubdiv's
  // limit stencils (Far::LimitStencilTableFactory: its own patch lookup, basis evaluation and
  // stencil accumulation), a path independent of basis(): used for boundary deviation. Slower than
  // basis() (a stencil table per call).
  Vec3 limit_point(int ptex, Vec2 uv, const std::vector<Vec3>& points) const;

 private:
  struct Osd;
  std::size_t vertex_count_;
  std::vector<std::vector<int>> faces_;
  std::vector<int> ptex_face_;
  std::unique_ptr<Osd> osd_;
};

}  // namespace pl
