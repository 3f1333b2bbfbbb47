#include "render/gpu_surface_batch.hpp"

#include <stdexcept>

namespace pl {

namespace {

// Attribute locations shared with surface.vert.glsl.
constexpr GLuint kPosition = 0, kNormal = 1, kCurvature = 2;

void attribute(GLuint location, const gl::Buffer& buffer, GLint components) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
}

}  // namespace

GpuSurfaceBatch::GpuSurfaceBatch() {
  vao_.bind();
  positions_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  normals_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  curvatures_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  attribute(kPosition, positions_, 3);
  attribute(kNormal, normals_, 3);
  attribute(kCurvature, curvatures_, 4);
  indices_.data(GL_ELEMENT_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
}

bool GpuSurfaceBatch::same_counts(const Range& r, const SurfaceMesh& mesh) const {
  return r.vertices == mesh.positions.size() && r.indices == 3 * mesh.triangles.size();
}

std::size_t GpuSurfaceBatch::update(std::span<const SurfaceMesh> meshes) {
  bool relayout = meshes.size() != ranges_.size();
  for (std::size_t i = 0; i < meshes.size() && !relayout; ++i)
    relayout = ranges_[i].revision != meshes[i].revision && !same_counts(ranges_[i], meshes[i]);
  if (relayout) {
    layout(meshes);
    return meshes.size();
  }
  std::size_t uploaded = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (ranges_[i].revision != meshes[i].revision) {
      upload_attributes(ranges_[i], meshes[i]);
      ranges_[i].revision = meshes[i].revision;
      ++uploaded;
    }
  return uploaded;
}

void GpuSurfaceBatch::update_surface(std::size_t i, const SurfaceMesh& mesh) {
  Range& r = ranges_.at(i);
  if (!same_counts(r, mesh))
    throw std::invalid_argument("GpuSurfaceBatch::update_surface: the surface's counts changed");
  upload_attributes(r, mesh);
  r.revision = mesh.revision;
}

void GpuSurfaceBatch::layout(std::span<const SurfaceMesh> meshes) {
  ranges_.clear();
  vertex_count_ = index_count_ = 0;
  for (const SurfaceMesh& m : meshes) {
    Range r;
    r.first_vertex = vertex_count_;
    r.vertices = m.positions.size();
    r.first_index = index_count_;
    r.indices = 3 * m.triangles.size();
    r.revision = m.revision;
    vertex_count_ += r.vertices;
    index_count_ += r.indices;
    ranges_.push_back(r);
  }
  // Allocate, then fill each range like an in-place update.
  positions_.data(GL_ARRAY_BUFFER, nullptr, 3 * vertex_count_ * sizeof(float), GL_DYNAMIC_DRAW);
  normals_.data(GL_ARRAY_BUFFER, nullptr, 3 * vertex_count_ * sizeof(float), GL_DYNAMIC_DRAW);
  curvatures_.data(GL_ARRAY_BUFFER, nullptr, 4 * vertex_count_ * sizeof(float), GL_DYNAMIC_DRAW);
  std::vector<uint32_t> indices;
  indices.reserve(index_count_);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    upload_attributes(ranges_[i], meshes[i]);
    // Indices refer to the batch's vertices: one call draws every surface.
    const auto base = static_cast<uint32_t>(ranges_[i].first_vertex);
    for (const auto& t : meshes[i].triangles)
      indices.insert(indices.end(), {t[0] + base, t[1] + base, t[2] + base});
  }
  vao_.bind();
  indices_.data(GL_ELEMENT_ARRAY_BUFFER, indices.data(), indices.size() * sizeof(uint32_t),
                GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
}

void GpuSurfaceBatch::upload_attributes(const Range& r, const SurfaceMesh& mesh) {
  const std::size_t n = r.vertices;
  if (n == 0) return;
  scratch_.resize(4 * n);
  auto send = [&](const gl::Buffer& b, std::size_t components) {
    b.sub_data(GL_ARRAY_BUFFER, scratch_.data(), components * n * sizeof(float),
               components * r.first_vertex * sizeof(float));
  };
  auto vec3s = [&](const std::vector<Vec3>& v) {
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) scratch_[3 * i + k] = static_cast<float>(v[i][k]);
  };
  vec3s(mesh.positions);
  send(positions_, 3);
  vec3s(mesh.normals);
  send(normals_, 3);
  for (std::size_t i = 0; i < n; ++i) {
    scratch_[4 * i + 0] = static_cast<float>(mesh.gaussian[i]);
    scratch_[4 * i + 1] = static_cast<float>(mesh.mean[i]);
    scratch_[4 * i + 2] = static_cast<float>(mesh.kmin[i]);
    scratch_[4 * i + 3] = static_cast<float>(mesh.kmax[i]);
  }
  send(curvatures_, 4);
}

void GpuSurfaceBatch::draw() const {
  if (index_count_ == 0) return;
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
}

void GpuSurfaceBatch::draw_surface(std::size_t i) const {
  if (i >= ranges_.size() || ranges_[i].indices == 0) return;
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(ranges_[i].indices), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(ranges_[i].first_index * sizeof(uint32_t)));
}

}  // namespace pl
