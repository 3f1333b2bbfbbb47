#include "render/gpu_scene.hpp"

namespace pl {

namespace {

// Attribute locations shared with the shaders (layout(location = N) there).
constexpr GLuint kPosition = 0, kNormal = 1, kCurvature = 2, kTag = 1;

void attribute(GLuint location, const gl::Buffer& buffer, GLint components) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
}

}  // namespace

GpuSurface::GpuSurface(const SurfaceMesh& mesh) {
  vao_.bind();
  upload_attributes(mesh, true);
  attribute(kPosition, positions_, 3);
  attribute(kNormal, normals_, 3);
  attribute(kCurvature, curvatures_, 4);
  indices_.data(GL_ELEMENT_ARRAY_BUFFER, mesh.triangles.data(),
                mesh.triangles.size() * sizeof(mesh.triangles[0]), GL_STATIC_DRAW);
  index_count_ = static_cast<GLsizei>(mesh.triangles.size() * 3);
  glBindVertexArray(0);
  revision_ = mesh.revision;
}

void GpuSurface::update(const SurfaceMesh& mesh) {
  if (mesh.positions.size() == vertex_count_ &&
      static_cast<GLsizei>(mesh.triangles.size() * 3) == index_count_) {
    upload_attributes(mesh, false);
    revision_ = mesh.revision;
  } else {
    *this = GpuSurface(mesh);
  }
}

void GpuSurface::upload_attributes(const SurfaceMesh& mesh, bool reallocate) {
  const std::size_t n = mesh.positions.size();
  vertex_count_ = n;
  auto send = [&](const gl::Buffer& b, std::size_t floats) {
    if (reallocate)
      b.data(GL_ARRAY_BUFFER, scratch_.data(), floats * sizeof(float), GL_DYNAMIC_DRAW);
    else
      b.sub_data(GL_ARRAY_BUFFER, scratch_.data(), floats * sizeof(float));
  };
  scratch_.resize(4 * n);
  auto vec3s = [&](const std::vector<Vec3>& v) {
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) scratch_[3 * i + k] = static_cast<float>(v[i][k]);
  };
  vec3s(mesh.positions);
  send(positions_, 3 * n);
  vec3s(mesh.normals);
  send(normals_, 3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    scratch_[4 * i + 0] = static_cast<float>(mesh.gaussian[i]);
    scratch_[4 * i + 1] = static_cast<float>(mesh.mean[i]);
    scratch_[4 * i + 2] = static_cast<float>(mesh.kmin[i]);
    scratch_[4 * i + 3] = static_cast<float>(mesh.kmax[i]);
  }
  send(curvatures_, 4 * n);
}

void GpuSurface::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

GpuPrimitives::GpuPrimitives() {
  vao_.bind();
  positions_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  tags_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  attribute(kPosition, positions_, 3);
  attribute(kTag, tags_, 1);
  glBindVertexArray(0);
}

void GpuPrimitives::set(const std::vector<Vec3>& vertices, const std::vector<float>& tags) {
  std::vector<float> xyz;
  xyz.reserve(vertices.size() * 3);
  for (const Vec3& p : vertices)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  std::vector<float> t = tags;
  t.resize(vertices.size(), 0.0f);
  positions_.data(GL_ARRAY_BUFFER, xyz.data(), xyz.size() * sizeof(float), GL_DYNAMIC_DRAW);
  tags_.data(GL_ARRAY_BUFFER, t.data(), t.size() * sizeof(float), GL_DYNAMIC_DRAW);
  count_ = static_cast<GLsizei>(vertices.size());
}

void GpuPrimitives::draw(GLenum mode) const {
  if (count_ == 0) return;
  glBindVertexArray(vao_.id());
  glDrawArrays(mode, 0, count_);
}

void GpuScene::update(const DrawScene& scene) {
  if (surfaces_.size() != scene.surfaces.size()) {
    surfaces_.clear();
    for (const SurfaceMesh& m : scene.surfaces) surfaces_.emplace_back(m);
  } else {
    for (std::size_t i = 0; i < surfaces_.size(); ++i)
      if (surfaces_[i].revision() != scene.surfaces[i].revision)
        surfaces_[i].update(scene.surfaces[i]);
  }
  // Control net: segments as GL_LINES pairs; points tagged with their kind.
  std::vector<Vec3> lines;
  for (const auto& s : scene.net.segments) {
    lines.push_back(scene.net.points.at(s[0]));
    lines.push_back(scene.net.points.at(s[1]));
  }
  net_lines_.set(lines, {});
  std::vector<float> kinds;
  for (ControlPointKind k : scene.net.kinds) kinds.push_back(static_cast<float>(k));
  net_points_.set(scene.net.points, kinds);
  auto polylines = [](const std::vector<Polyline>& ls) {
    std::vector<Vec3> out;
    for (const Polyline& l : ls)
      for (std::size_t i = 0; i + 1 < l.size(); ++i) {
        out.push_back(l[i]);
        out.push_back(l[i + 1]);
      }
    return out;
  };
  curves_.set(polylines(scene.network_curves), {});
  borders_.set(polylines(scene.borders), {});
}

}  // namespace pl
