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

// A polyline as GL_LINES pairs.
void add_polyline(const std::vector<Vec3>& l, std::vector<Vec3>& out) {
  for (std::size_t i = 0; i + 1 < l.size(); ++i) {
    out.push_back(l[i]);
    out.push_back(l[i + 1]);
  }
}

std::vector<Vec3> polylines(const std::vector<Polyline>& ls) {
  std::vector<Vec3> out;
  for (const Polyline& l : ls) add_polyline(l, out);
  return out;
}

}  // namespace

GpuPrimitives::GpuPrimitives() {
  vao_.bind();
  positions_.data(GL_ARRAY_BUFFER, nullptr, 0, GL_DYNAMIC_DRAW);
  attribute(kPosition, positions_, 3);
  // Tags and offsets: arrays only once set() has some (the attribute is bound to its buffer then).
  glBindVertexArray(0);
}

namespace {

// Vertices compared and re-sent in runs of this many: an edit that moved a few curves sends a
// few runs, not the whole array.
constexpr std::size_t kRunVertices = 256;

}  // namespace

void GpuPrimitives::send(const gl::Buffer& buffer, std::vector<float>& copy, std::size_t width,
                         bool reallocate) {
  if (reallocate || copy.size() != scratch_.size()) {
    buffer.data(GL_ARRAY_BUFFER, scratch_.data(), scratch_.size() * sizeof(float), GL_DYNAMIC_DRAW);
    copy = scratch_;
    return;
  }
  // Same size: only the runs that differ from what the buffer holds.
  const std::size_t run = kRunVertices * width;
  for (std::size_t at = 0; at < scratch_.size();) {
    const std::size_t end = std::min(scratch_.size(), at + run);
    if (!std::equal(scratch_.begin() + std::ptrdiff_t(at), scratch_.begin() + std::ptrdiff_t(end),
                    copy.begin() + std::ptrdiff_t(at))) {
      std::size_t last = end;  // extend over the following differing runs: one call each stretch
      while (last < scratch_.size()) {
        const std::size_t next = std::min(scratch_.size(), last + run);
        if (std::equal(scratch_.begin() + std::ptrdiff_t(last),
                       scratch_.begin() + std::ptrdiff_t(next),
                       copy.begin() + std::ptrdiff_t(last)))
          break;
        last = next;
      }
      buffer.sub_data(GL_ARRAY_BUFFER, scratch_.data() + at, (last - at) * sizeof(float),
                      at * sizeof(float));
      std::copy(scratch_.begin() + std::ptrdiff_t(at), scratch_.begin() + std::ptrdiff_t(last),
                copy.begin() + std::ptrdiff_t(at));
      at = last;
    } else {
      at = end;
    }
  }
}

void GpuPrimitives::set(const std::vector<Vec3>& vertices, const std::vector<float>& tags,
                        const std::vector<Vec3>& offsets) {
  const std::size_t n = vertices.size();
  auto floats = [&](const std::vector<Vec3>& v) {
    scratch_.assign(n * 3, 0.0f);
    for (std::size_t i = 0; i < std::min(n, v.size()); ++i)
      for (int k = 0; k < 3; ++k) scratch_[3 * i + k] = static_cast<float>(v[i][k]);
  };
  vao_.bind();
  floats(vertices);
  send(positions_, positions_copy_, 3, false);
  const bool had_tags = has_tags_, had_offsets = has_offsets_;
  has_tags_ = !tags.empty() && n > 0;
  if (has_tags_) {
    scratch_.assign(tags.begin(), tags.begin() + std::ptrdiff_t(std::min(n, tags.size())));
    scratch_.resize(n, 0.0f);
    send(tags_, tags_copy_, 1, !had_tags);
    attribute(kTag, tags_, 1);
  } else {
    glDisableVertexAttribArray(kTag);
    tags_copy_.clear();
  }
  has_offsets_ = !offsets.empty() && n > 0;
  if (has_offsets_) {
    floats(offsets);
    send(offsets_, offsets_copy_, 3, !had_offsets);
    attribute(kOffset, offsets_, 3);
  } else {
    glDisableVertexAttribArray(kOffset);
    offsets_copy_.clear();
  }
  glBindVertexArray(0);
  count_ = static_cast<GLsizei>(n);
}

void GpuCombs::set(std::span<const CurvatureComb* const> combs, std::size_t own, double max_tooth) {
  std::vector<Vec3> points, offsets, tip_points, tip_offsets;
  const Vec3 zero(0);
  for (std::size_t k = 0; k < combs.size(); ++k) {
    if (k == own) {
      own_teeth = static_cast<GLsizei>(points.size());
      own_envelope = static_cast<GLsizei>(tip_points.size());
    }
    const CurvatureComb& c = *combs[k];
    if (c.teeth.size() != c.points.size()) continue;  // a border without a comb
    const std::size_t n = c.points.size();
    auto tooth = [&](std::size_t i) {
      const double len = glm::length(c.teeth[i]);
      return max_tooth > 0 && len > max_tooth ? c.teeth[i] * (max_tooth / len) : c.teeth[i];
    };
    for (std::size_t i = 0; i < n; ++i) {
      // Teeth at every tooth_stride-th sample and always at the last one (the curve's end). A
      // zero tooth, and the envelope where both ends have one, would be drawn as a dot (the
      // line shader widens a zero-length segment into a square): where the curve is straight
      // or degenerate the envelope is the curve itself and nothing is drawn over it.
      if ((i % std::size_t(std::max(c.tooth_stride, 1)) == 0 || i + 1 == n) && c.teeth[i] != zero) {
        points.insert(points.end(), {c.points[i], c.points[i]});
        offsets.insert(offsets.end(), {zero, tooth(i)});
      }
      if (i + 1 < n && (c.teeth[i] != zero || c.teeth[i + 1] != zero)) {
        tip_points.insert(tip_points.end(), {c.points[i], c.points[i + 1]});
        tip_offsets.insert(tip_offsets.end(), {tooth(i), tooth(i + 1)});
      }
    }
  }
  if (own >= combs.size()) {
    own_teeth = static_cast<GLsizei>(points.size());
    own_envelope = static_cast<GLsizei>(tip_points.size());
  }
  teeth.set(points, {}, offsets);
  envelope.set(tip_points, {}, tip_offsets);
}

void GpuPrimitives::draw(GLenum mode, GLsizei count) const {
  const GLsizei n = count < 0 ? count_ : std::min(count, count_);
  if (n == 0) return;
  glBindVertexArray(vao_.id());
  // The current value of a disabled attribute is context state, not the vertex array's: set it
  // for every draw.
  if (!has_tags_) glVertexAttrib1f(kTag, 0.0f);
  if (!has_offsets_) glVertexAttrib3f(kOffset, 0.0f, 0.0f, 0.0f);
  glDrawArrays(mode, 0, n);
}

void GpuScene::update(const DrawScene& scene) {
  update_geometry(scene);
  borders_.set(polylines(scene.borders), {});
  own_border_vertices_ = -1;  // a DrawScene's borders do not say which are network curves
  std::vector<const CurvatureComb*> network, borders, free;
  for (const CurvatureComb& c : scene.network_combs) network.push_back(&c);
  for (const CurvatureComb& c : scene.border_combs) borders.push_back(&c);
  for (const CurvatureComb& c : scene.free_curve_combs) free.push_back(&c);
  set_combs(network, borders, scene.border_on_network, free);
}

void GpuScene::update_geometry(const DrawScene& scene) {
  update_meshes_and_curves(scene);
  set_net(scene.net, scene.arrows);
}

void GpuScene::update_meshes_and_curves(const DrawScene& scene) {
  surfaces_.update(scene.surfaces);
  closed_orientation_ = scene.closed_orientation;
  surface_bounds_ = Box();
  for (const SurfaceMesh& m : scene.surfaces)
    for (const Vec3& p : m.positions) surface_bounds_.add(p);
  set_highlights(scene.highlights);
  curves_.set(polylines(scene.network_curves), {});
  free_curves_.set(polylines(scene.free_curves), {});
  const Box box = scene.bounds();
  diagonal_ = box.empty() ? 0.0 : glm::length(box.hi - box.lo);
}

void GpuScene::set_net(const ControlNet& net, std::span<const Arrow> arrows) {
  // Control net: segments as GL_LINES pairs, split by role; points tagged with their style,
  // derived ones first.
  std::vector<Vec3> lines, derived_lines;
  for (const auto& s : net.segments) {
    const bool derived =
        net.role(s[0]) == PointRole::Derived || net.role(s[1]) == PointRole::Derived;
    auto& out = derived ? derived_lines : lines;
    out.push_back(net.points.at(s[0]));
    out.push_back(net.points.at(s[1]));
  }
  net_lines_.set(lines, {});
  derived_net_lines_.set(derived_lines, {});
  std::vector<Vec3> points;
  std::vector<float> tags;
  for (PointRole role : {PointRole::Derived, PointRole::Editable})
    for (std::size_t i = 0; i < net.points.size(); ++i) {
      if (net.role(i) != role) continue;
      const ControlPointKind kind =
          i < net.kinds.size() ? net.kinds[i] : ControlPointKind::Boundary;
      const int tag = point_style_tag(kind, role);
      points.push_back(net.points[i]);
      tags.push_back(static_cast<float>(tag));
    }
  net_points_.set(points, tags);
  point_styles_ = point_style_bits(net);
  std::vector<Vec3> arrow_ends;
  std::vector<float> arrow_tags;
  for (const Arrow& a : arrows) {
    arrow_ends.push_back(a.base);
    arrow_ends.push_back(a.tip);
    arrow_tags.insert(arrow_tags.end(), 2, static_cast<float>(a.kind));
  }
  arrows_.set(arrow_ends, arrow_tags);
  arrow_kinds_ = arrow_kind_bits({arrows.begin(), arrows.end()});
}

void GpuScene::set_highlights(const std::vector<Polyline>& highlights) {
  highlights_.set(polylines(highlights), {});
}

void GpuScene::update_curves(std::span<const CurvatureComb* const> network_combs,
                             std::span<const CurvatureComb* const> borders,
                             const std::vector<bool>& border_on_network,
                             std::span<const CurvatureComb* const> free_combs) {
  // Borders that are not network curves first: with the network curves shown, the others are
  // the same curves under them and are not drawn.
  std::vector<Vec3> lines;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) own_border_vertices_ = static_cast<GLsizei>(lines.size());
    for (std::size_t i = 0; i < borders.size(); ++i) {
      const bool on_network = i < border_on_network.size() && border_on_network[i];
      if (on_network == (pass == 1)) add_polyline(borders[i]->points, lines);
    }
  }
  borders_.set(lines, {});
  set_combs(network_combs, borders, border_on_network, free_combs);
}

void GpuScene::set_combs(std::span<const CurvatureComb* const> network_combs,
                         std::span<const CurvatureComb* const> borders,
                         const std::vector<bool>& border_on_network,
                         std::span<const CurvatureComb* const> free_combs) {
  // The border combs that are not network edges' first, so that they can be drawn alone.
  std::vector<const CurvatureComb*> ordered;
  ordered.reserve(borders.size());
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < borders.size(); ++i) {
      const bool on_network = i < border_on_network.size() && border_on_network[i];
      if (on_network == (pass == 1)) ordered.push_back(borders[i]);
    }
  std::size_t own = 0;
  for (std::size_t i = 0; i < borders.size(); ++i)
    own += !(i < border_on_network.size() && border_on_network[i]);
  std::vector<const CurvatureComb*> all(network_combs.begin(), network_combs.end());
  all.insert(all.end(), borders.begin(), borders.end());
  all.insert(all.end(), free_combs.begin(), free_combs.end());
  comb_scale_ = automatic_comb_scale_of(all, diagonal_);
  comb_reference_length_ = kDefaultCombFraction * diagonal_;
  const double max_tooth =
      comb_scale_ > 0 ? kCombToothClamp * comb_reference_length_ / comb_scale_ : 0.0;
  network_combs_.set(network_combs, network_combs.size(), max_tooth);
  border_combs_.set(ordered, own, max_tooth);
  free_combs_.set(free_combs, free_combs.size(), max_tooth);
}

}  // namespace pl
