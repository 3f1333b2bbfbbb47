#include "render/gpu_scene.hpp"

#include <algorithm>

namespace pl {

namespace {

// Attribute locations shared with the shaders (layout(location = N) there).
constexpr GLuint kPosition = 0, kNormal = 1, kCurvature = 2, kTag = 1, kOffset = 2;

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
  offsets_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  attribute(kPosition, positions_, 3);
  attribute(kTag, tags_, 1);
  attribute(kOffset, offsets_, 3);
  glBindVertexArray(0);
}

void GpuPrimitives::set(const std::vector<Vec3>& vertices, const std::vector<float>& tags,
                        const std::vector<Vec3>& offsets) {
  auto floats = [n = vertices.size()](const std::vector<Vec3>& v) {
    std::vector<float> xyz(n * 3, 0.0f);
    for (std::size_t i = 0; i < std::min(n, v.size()); ++i)
      for (int k = 0; k < 3; ++k) xyz[3 * i + k] = static_cast<float>(v[i][k]);
    return xyz;
  };
  const std::vector<float> xyz = floats(vertices), offset_xyz = floats(offsets);
  std::vector<float> t = tags;
  t.resize(vertices.size(), 0.0f);
  positions_.data(GL_ARRAY_BUFFER, xyz.data(), xyz.size() * sizeof(float), GL_DYNAMIC_DRAW);
  tags_.data(GL_ARRAY_BUFFER, t.data(), t.size() * sizeof(float), GL_DYNAMIC_DRAW);
  offsets_.data(GL_ARRAY_BUFFER, offset_xyz.data(), offset_xyz.size() * sizeof(float),
                GL_DYNAMIC_DRAW);
  count_ = static_cast<GLsizei>(vertices.size());
}

void GpuCombs::set(const std::vector<CurvatureComb>& combs) {
  std::vector<Vec3> points, offsets, tip_points, tip_offsets;
  for (const CurvatureComb& c : combs) {
    const std::size_t n = c.points.size();
    const Vec3 zero(0);
    for (std::size_t i = 0; i < n; ++i) {
      // Teeth at every tooth_stride-th sample and always at the last one (the curve's end). A
      // zero tooth, and the envelope where both ends have one, would be drawn as a dot (the
      // line shader widens a zero-length segment into a square): where the curve is straight
      // or degenerate the envelope is the curve itself and nothing is drawn over it.
      if ((i % std::size_t(std::max(c.tooth_stride, 1)) == 0 || i + 1 == n) && c.teeth[i] != zero) {
        points.insert(points.end(), {c.points[i], c.points[i]});
        offsets.insert(offsets.end(), {Vec3(0), c.teeth[i]});
      }
      if (i + 1 < n && (c.teeth[i] != zero || c.teeth[i + 1] != zero)) {
        tip_points.insert(tip_points.end(), {c.points[i], c.points[i + 1]});
        tip_offsets.insert(tip_offsets.end(), {c.teeth[i], c.teeth[i + 1]});
      }
    }
  }
  teeth.set(points, {}, offsets);
  envelope.set(tip_points, {}, tip_offsets);
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
  network_combs_.set(scene.network_combs);
  border_combs_.set(scene.border_combs);
  std::vector<CurvatureComb> own;
  for (std::size_t i = 0; i < scene.border_combs.size(); ++i)
    if (i >= scene.border_on_network.size() || !scene.border_on_network[i])
      own.push_back(scene.border_combs[i]);
  patch_border_combs_.set(own);
  std::vector<CurvatureComb> all = scene.network_combs;
  all.insert(all.end(), scene.border_combs.begin(), scene.border_combs.end());
  const Box box = scene.bounds();
  const double diagonal = box.empty() ? 0.0 : glm::length(box.hi - box.lo);
  comb_scale_ = automatic_comb_scale(all, diagonal);
  comb_reference_length_ = kDefaultCombFraction * diagonal;
}

}  // namespace pl
