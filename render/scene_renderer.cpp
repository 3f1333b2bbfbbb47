#include "render/scene_renderer.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <limits>

namespace pl {

namespace {

constexpr int kColorMapEntries = 1024;
// The halo under a selection's outline: dark enough to part the outline from a light colour,
// wider by this many pixels.
constexpr std::array<float, 4> kOutlineHalo = {0.05f, 0.05f, 0.07f, 0.75f};
constexpr float kOutlineHaloExtra = 3.0f;
// Point sprites are pulled towards the eye by this many radii (point.vert.glsl).
constexpr float kPointDepthPush = 3.0f;

void set(GLint loc, const Vec3& v) {
  glUniform3f(loc, static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

void set(GLint loc, const Rgb& c) {
  glUniform3f(loc, c[0], c[1], c[2]);
}

template <std::size_t N>
void set(GLint loc, const std::array<Rgb, N>& colors) {
  glUniform3fv(loc, static_cast<GLsizei>(N), colors[0].data());
}

// True when the eye is outside `box` and the near clipping plane cuts nothing of it.
bool sees_outside_only(const Camera& camera, const Box& box) {
  if (box.empty()) return false;
  const Vec3 eye = camera.eye(), f = camera.forward();
  const bool inside = eye.x >= box.lo.x && eye.x <= box.hi.x && eye.y >= box.lo.y &&
                      eye.y <= box.hi.y && eye.z >= box.lo.z && eye.z <= box.hi.z;
  if (inside) return false;
  double nearest = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner(c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y,
                      c & 4 ? box.hi.z : box.lo.z);
    nearest = std::min(nearest, glm::dot(corner - eye, f));
  }
  return nearest > camera.clip_planes()[0];
}

}  // namespace

SceneRenderer::SceneRenderer()
    : surface_("surface.vert.glsl", "", "surface.frag.glsl"),
      lines_("line.vert.glsl", "line.geom.glsl", "line.frag.glsl"),
      points_("point.vert.glsl", "point.geom.glsl", "point.frag.glsl"),
      arrows_("line.vert.glsl", "arrow.geom.glsl", "arrow.frag.glsl"),
      backdrop_("backdrop.vert.glsl", "", "backdrop.frag.glsl"),
      tint_("tint.vert.glsl", "", "tint.frag.glsl") {
  const std::vector<float> table = color_map_table(kColorMapEntries);
  glBindTexture(GL_TEXTURE_2D, color_map_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, kColorMapEntries, 1, 0, GL_RGB, GL_FLOAT, table.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl::check_error("SceneRenderer setup");
}

void SceneRenderer::draw(const GpuScene& scene, const Camera& camera,
                         const DisplaySettings& settings, const ColorRange& range,
                         const Viewport& v) const {
  glViewport(v.x, v.y, v.width, v.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);

  const double aspect = double(v.width) / double(v.height);
  const glm::mat4 vp(camera.projection(aspect) * camera.view());
  // Studio lights fixed to the camera: key from the upper left, fill from the lower right.
  const Vec3 f = camera.forward(), u = camera.up(), r = camera.right();
  const Vec3 key = glm::normalize(-0.55 * f + 0.60 * u - 0.50 * r);
  const Vec3 fill = glm::normalize(-0.70 * f - 0.30 * u + 0.65 * r);
  // The shaded mode's key grazes more (about 70 degrees off the view axis) for contrast.
  const Vec3 shade = glm::normalize(-0.35 * f + 0.62 * u - 0.70 * r);

  surface_.use();
  glUniformMatrix4fv(surface_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform1i(surface_.uniform("u_base"), static_cast<int>(settings.base));
  glUniform1i(surface_.uniform("u_curvature_index"), static_cast<int>(settings.curvature));
  set(surface_.uniform("u_eye"), camera.eye());
  set(surface_.uniform("u_key_light"), key);
  set(surface_.uniform("u_fill_light"), fill);
  set(surface_.uniform("u_shade_light"), shade);
  set(surface_.uniform("u_camera_up"), u);
  set(surface_.uniform("u_camera_forward"), f);
  glUniform1i(surface_.uniform("u_isophote_lines"), shows_isophote_lines(settings) ? 1 : 0);
  set(surface_.uniform("u_isophote_direction"), glm::normalize(settings.isophote_direction));
  glUniform1f(surface_.uniform("u_isophote_count"), float(settings.isophote_count));
  glUniform1f(surface_.uniform("u_isophote_width"),
              float(settings.isophote_width_px * v.pixel_scale));
  glUniform1f(surface_.uniform("u_zebra_count"), float(settings.zebra_count));
  glUniform1f(surface_.uniform("u_zebra_width"), float(settings.zebra_width));
  glUniform1f(surface_.uniform("u_range_lo"), float(range.lo));
  glUniform1f(surface_.uniform("u_range_hi"), float(range.hi));
  glUniform1i(surface_.uniform("u_curvature_lit"), settings.curvature_lighting ? 1 : 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, color_map_.id());
  glUniform1i(surface_.uniform("u_color_map"), 0);
  // A solid seen from outside, with nothing of it cut by the near plane: its inner side is
  // hidden, so it is not drawn (on a CPU rasteriser that halves the surfaces' cost).
  const int closed = scene.closed_orientation();
  if (closed != 0 && sees_outside_only(camera, scene.surface_bounds())) {
    glEnable(GL_CULL_FACE);
    glCullFace(closed > 0 ? GL_BACK : GL_FRONT);
  }
  scene.surfaces().draw();
  glDisable(GL_CULL_FACE);

  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const float s = static_cast<float>(v.pixel_scale);
  // Combs go on the curves shown; `combs` alone shows the network curves with theirs, or the
  // borders of a scene without a network.
  const bool lone_combs = settings.combs && !settings.borders && !settings.network_curves;
  const bool has_network = !scene.network_curves().empty();
  const bool borders = settings.borders || (lone_combs && !has_network);
  const bool network = settings.network_curves || (lone_combs && has_network);
  // Curves behind a surface show faintly, as every overlay does: a closed shape's back is read,
  // not confused with its front.
  // A network face's border is its edge's curve: with the network curves shown it is not drawn
  // again under them.
  if (borders)
    draw_lines(scene.borders(), vp, v, palette::kBorder, 0.85f, 1.4f * s, true, 0.0f, 0.0f,
               network ? scene.own_border_vertices() : -1);
  if (network)
    draw_lines(scene.network_curves(), vp, v, palette::kNetworkCurve, 1.0f, 2.6f * s, true);
  // Free curves are objects of their own: always shown.
  draw_lines(scene.free_curves(), vp, v, palette::kNetworkCurve, 1.0f, 2.6f * s, true);
  if (settings.combs) {
    const double per_curvature =
        settings.comb_length.value_or(scene.comb_scale()) * settings.comb_scale;
    const double cap = kCombCap * scene.comb_reference_length() * settings.comb_scale;
    // A network face's border comb is its edge's: drawn once, with the network's.
    if (borders) draw_combs(scene.border_combs(), network, vp, v, float(per_curvature), float(cap));
    if (network) draw_combs(scene.network_combs(), false, vp, v, float(per_curvature), float(cap));
    draw_combs(scene.free_curve_combs(), false, vp, v, float(per_curvature), float(cap));
  }
  if (settings.control_net) draw_net(scene, camera, vp, v);
  // Highlights last: what the user is pointed at is never under another overlay.
  draw_lines(scene.highlights(), vp, v, palette::kHighlight, 1.0f, 4.0f * s, true);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  gl::check_error("SceneRenderer::draw");
}

void SceneRenderer::draw_net(const GpuScene& scene, const Camera& camera, const glm::mat4& vp,
                             const Viewport& v) const {
  const float s = static_cast<float>(v.pixel_scale);
  draw_lines(scene.derived_net_lines(), vp, v, palette::kDerivedNetLine, 0.8f, 1.0f * s, true);
  draw_lines(scene.net_lines(), vp, v, palette::kNetLine, 0.9f, 1.3f * s, true);
  glDepthMask(GL_FALSE);  // overlays never hide each other's parts
  if (!scene.arrows().empty()) {
    arrows_.use();
    glUniformMatrix4fv(arrows_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform1f(arrows_.uniform("u_offset_scale"), 0.0f);
    glUniform1f(arrows_.uniform("u_offset_max"), 0.0f);
    glUniform2f(arrows_.uniform("u_viewport_size"), float(v.width), float(v.height));
    glUniform1f(arrows_.uniform("u_width"), kArrowWidth * s);
    glUniform1f(arrows_.uniform("u_head"), kArrowHead * s);
    glUniform1f(arrows_.uniform("u_depth_bias"), kOverlayDepthBias);
    set(arrows_.uniform("u_colors"),
        std::array<Rgb, 2>{palette::kTangentArrow, palette::kTwistArrow});
    for (const bool hidden : {true, false}) {
      glDepthFunc(hidden ? GL_GREATER : GL_LEQUAL);
      glUniform1f(arrows_.uniform("u_alpha"), hidden ? kHiddenAlpha : 1.0f);
      scene.arrows().draw(GL_LINES);
    }
  }
  if (!scene.net_points().empty()) {
    const double aspect = double(v.width) / double(v.height);
    const glm::mat4 view(camera.view()), projection(camera.projection(aspect));
    points_.use();
    glUniformMatrix4fv(points_.uniform("u_view"), 1, GL_FALSE, glm::value_ptr(view));
    glUniformMatrix4fv(points_.uniform("u_projection"), 1, GL_FALSE, glm::value_ptr(projection));
    glUniform2f(points_.uniform("u_viewport_size"), float(v.width), float(v.height));
    glUniform1f(points_.uniform("u_size"), kPointSize * s);
    glUniform1f(points_.uniform("u_derived_scale"), kDerivedPointScale);
    glUniform1f(points_.uniform("u_depth_push"), kPointDepthPush);
    set(points_.uniform("u_kind_colors"), palette::kPointKinds);
    set(points_.uniform("u_outline"), palette::kPointOutline);
    set(points_.uniform("u_derived_fill"), palette::kDerivedPointFill);
    // Points behind a surface first, faded, then the visible ones.
    for (const bool hidden : {true, false}) {
      glDepthFunc(hidden ? GL_GREATER : GL_LEQUAL);
      glUniform1f(points_.uniform("u_alpha"), hidden ? kHiddenPointAlpha : 1.0f);
      scene.net_points().draw(GL_POINTS);
    }
  }
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
}

void SceneRenderer::draw_backdrop(const Viewport& v) const {
  glViewport(v.x, v.y, v.width, v.height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  backdrop_.use();
  glUniform4f(backdrop_.uniform("u_viewport"), float(v.x), float(v.y), float(v.width),
              float(v.height));
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

void SceneRenderer::draw_tint(const GpuScene& scene, std::span<const int> surfaces,
                              const Camera& camera, const std::array<float, 4>& color,
                              const Viewport& v) const {
  if (surfaces.empty()) return;
  glViewport(v.x, v.y, v.width, v.height);
  const glm::mat4 vp(camera.projection(double(v.width) / double(v.height)) * camera.view());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  // The same triangles as the surface pass, pulled forward so they win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  tint_.use();
  glUniformMatrix4fv(tint_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform4f(tint_.uniform("u_color"), color[0], color[1], color[2], color[3]);
  for (int i : surfaces)
    if (i >= 0) scene.surfaces().draw_surface(std::size_t(i));
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  gl::check_error("SceneRenderer::draw_tint");
}

void SceneRenderer::draw_selection(const GpuScene& scene, std::span<const int> surfaces,
                                   const GpuPrimitives& outline, const Camera& camera,
                                   const DisplaySettings& settings, const SelectionStyle& style,
                                   const Viewport& v) const {
  if (!colours_carry_values(settings) && style.tint[3] > 0)
    draw_tint(scene, surfaces, camera, style.tint, v);
  if (outline.empty()) return;
  // The halo where the outline is seen only: behind a surface the faint outline is enough.
  draw_guides(outline, camera, kOutlineHalo, style.line_width + kOutlineHaloExtra, false, v);
  draw_guides(outline, camera, style.line, style.line_width, style.show_hidden, v);
}

void SceneRenderer::draw_guides(const GpuPrimitives& lines, const Camera& camera,
                                const std::array<float, 4>& color, float width, bool show_hidden,
                                const Viewport& v) const {
  if (lines.empty()) return;
  glViewport(v.x, v.y, v.width, v.height);
  const glm::mat4 vp(camera.projection(double(v.width) / double(v.height)) * camera.view());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_lines(lines, vp, v, {color[0], color[1], color[2]}, color[3], width * float(v.pixel_scale),
             show_hidden);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  gl::check_error("SceneRenderer::draw_guides");
}

void SceneRenderer::draw_combs(const GpuCombs& combs, bool own_only, const glm::mat4& vp,
                               const Viewport& v, float offset_scale, float offset_max) const {
  if (!(offset_scale > 0)) return;  // every curve straight: no tooth has length
  const float s = static_cast<float>(v.pixel_scale);
  // A colour of their own (none of the curves', the point kinds' or the colour map's), teeth
  // thin and light so dense combs do not turn into a solid band, the envelope stronger: it is
  // what the eye follows. Parts behind a surface show faintly, as the control net does, since
  // teeth often pierce the surface they describe.
  draw_lines(combs.teeth, vp, v, palette::kCombTeeth, 0.55f, 1.0f * s, true, offset_scale,
             offset_max, own_only ? combs.own_teeth : -1);
  draw_lines(combs.envelope, vp, v, palette::kCombEnvelope, 0.95f, 1.8f * s, true, offset_scale,
             offset_max, own_only ? combs.own_envelope : -1);
}

void SceneRenderer::draw_lines(const GpuPrimitives& lines, const glm::mat4& vp, const Viewport& v,
                               const Rgb& color, float alpha, float width, bool show_hidden,
                               float offset_scale, float offset_max, GLsizei count) const {
  if (lines.empty() || count == 0) return;
  lines_.use();
  glUniformMatrix4fv(lines_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform1f(lines_.uniform("u_offset_scale"), offset_scale);
  glUniform1f(lines_.uniform("u_offset_max"), offset_max);
  glUniform2f(lines_.uniform("u_viewport_size"), float(v.width), float(v.height));
  glUniform1f(lines_.uniform("u_width"), width);
  glUniform1f(lines_.uniform("u_depth_bias"), kOverlayDepthBias);
  glDepthMask(GL_FALSE);  // overlays never hide each other's parts
  if (show_hidden) {
    glDepthFunc(GL_GREATER);
    glUniform4f(lines_.uniform("u_color"), color[0], color[1], color[2], alpha * kHiddenAlpha);
    lines.draw(GL_LINES, count);
    glDepthFunc(GL_LEQUAL);
  }
  glUniform4f(lines_.uniform("u_color"), color[0], color[1], color[2], alpha);
  lines.draw(GL_LINES, count);
  glDepthMask(GL_TRUE);
}

}  // namespace pl
