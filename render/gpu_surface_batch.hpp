// Every surface of a scene in one set of GPU buffers, drawn with one call. On a CPU rasteriser
// (llvmpipe) each draw call has a fixed cost: 1,536 surfaces drawn one by one cost 30-60 ms a
// frame before a single triangle was filled. Each surface keeps its own range of vertices and
// indices, so an edit that changed a few surfaces re-uploads those ranges only
// (glBufferSubData), and a selection tint can still draw single surfaces. When the number of
// vertices or triangles of any surface changes (a new density, a topology edit) the buffers are
// laid out and uploaded again.
#pragma once

#include <span>
#include <vector>

#include "core/mesh/surface_mesh.hpp"
#include "render/gl_objects.hpp"

namespace pl {

class GpuSurfaceBatch {
 public:
  GpuSurfaceBatch();
  // Brings the buffers up to `meshes`: a surface whose revision differs from the one uploaded
  // is re-uploaded in place when its counts are unchanged; otherwise everything is laid out
  // again. Returns the number of surfaces uploaded.
  std::size_t update(std::span<const SurfaceMesh> meshes);
  // Re-uploads surface i (same counts: in place; else everything is laid out again, which needs
  // every mesh, so this form needs equal counts and throws std::invalid_argument otherwise).
  void update_surface(std::size_t i, const SurfaceMesh& mesh);

  // Every surface in one call.
  void draw() const;
  // One surface (ignored when out of range).
  void draw_surface(std::size_t i) const;

  std::size_t size() const { return ranges_.size(); }
  std::size_t triangles() const { return index_count_ / 3; }

 private:
  struct Range {
    std::size_t first_vertex = 0, vertices = 0;
    std::size_t first_index = 0, indices = 0;
    uint64_t revision = 0;
  };
  void layout(std::span<const SurfaceMesh> meshes);
  // Converts and sends one surface's attributes to its range.
  void upload_attributes(const Range& r, const SurfaceMesh& mesh);
  bool same_counts(const Range& r, const SurfaceMesh& mesh) const;

  gl::VertexArray vao_;
  gl::Buffer positions_, normals_, curvatures_, indices_;
  std::vector<Range> ranges_;
  std::size_t vertex_count_ = 0, index_count_ = 0;
  std::vector<float> scratch_;  // reused conversion buffer: no allocation per drag update
};

}  // namespace pl
