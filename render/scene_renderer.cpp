#include "render/scene_renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace pl {

namespace {

constexpr int kColorMapEntries = 1024;
// Pulls overlay lines in front of the triangles they lie on; the triangles are chords of the
// curved surface, so a line sampled on the exact surface can sit slightly behind them.
constexpr float kOverlayDepthBias = 4e-4f;
// How visible hidden parts of the control net are: enough to read the structure behind the
// surface, faint enough not to be confused with the visible part.
constexpr float kHiddenAlpha = 0.22f;
// Teeth longer than this many reference lengths (the automatic length at the reference
// curvature, times the user's multiplier) are cut to it: near a cusp the curvature grows
// without bound, and one tooth across the whole picture hides everything else. The envelope is
// capped the same way, so a flat top on it marks a capped stretch.
constexpr double kCombCap = 3.0;

void set(GLint loc, const Vec3& v) {
  glUniform3f(loc, static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

}  // namespace

SceneRenderer::SceneRenderer()
    : surface_("surface.vert.glsl", "", "surface.frag.glsl"),
      lines_("line.vert.glsl", "line.geom.glsl", "line.frag.glsl"),
      points_("line.vert.glsl", "point.geom.glsl", "point.frag.glsl"),
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

  surface_.use();
  glUniformMatrix4fv(surface_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
  glUniform1i(surface_.uniform("u_base"), static_cast<int>(settings.base));
  glUniform1i(surface_.uniform("u_curvature_index"), static_cast<int>(settings.curvature));
  set(surface_.uniform("u_eye"), camera.eye());
  set(surface_.uniform("u_key_light"), key);
  set(surface_.uniform("u_fill_light"), fill);
  set(surface_.uniform("u_camera_up"), u);
  set(surface_.uniform("u_camera_forward"), f);
  glUniform1i(surface_.uniform("u_isophote_lines"), settings.isophote_lines ? 1 : 0);
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
  for (const GpuSurface& s : scene.surfaces()) s.draw();

  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const float s = static_cast<float>(v.pixel_scale);
  // Combs go on the curves shown; `combs` alone shows the network curves with theirs, or the
  // borders of a scene without a network.
  const bool lone_combs = settings.combs && !settings.borders && !settings.network_curves;
  const bool has_network = !scene.network_curves().empty();
  const bool borders = settings.borders || (lone_combs && !has_network);
  const bool network = settings.network_curves || (lone_combs && has_network);
  if (borders) draw_lines(scene.borders(), vp, v, {0.12f, 0.13f, 0.16f, 0.85f}, 1.4f * s, false);
  if (network)
    draw_lines(scene.network_curves(), vp, v, {0.05f, 0.30f, 0.62f, 1.0f}, 2.6f * s, false);
  if (settings.combs) {
    const double per_curvature =
        settings.comb_length.value_or(scene.comb_scale()) * settings.comb_scale;
    const double cap = kCombCap * scene.comb_reference_length() * settings.comb_scale;
    // A network face's border comb is its edge's: drawn once, with the network's.
    if (borders) draw_combs(scene.border_combs(), network, vp, v, float(per_curvature), float(cap));
    if (network) draw_combs(scene.network_combs(), false, vp, v, float(per_curvature), float(cap));
  }
  if (settings.control_net) {
    draw_lines(scene.net_lines(), vp, v, {0.20f, 0.22f, 0.26f, 0.9f}, 1.3f * s, true);
    points_.use();
    glUniformMatrix4fv(points_.uniform("u_view_projection"), 1, GL_FALSE, glm::value_ptr(vp));
    glUniform2f(points_.uniform("u_viewport_size"), float(v.width), float(v.height));
    glUniform1f(points_.uniform("u_size"), 9.0f * s);
    glUniform1f(points_.uniform("u_depth_bias"), 0.0f);
    // Boundary, Inner, Twin, Central: the core's ControlPointKind order.
    const float kinds[12] = {0.95f, 0.62f, 0.10f, 0.20f, 0.55f, 0.95f,
                             0.85f, 0.25f, 0.75f, 0.20f, 0.75f, 0.35f};
    glUniform3fv(points_.uniform("u_kind_colors"), 4, kinds);
    // Points are drawn over everything: they are what a designer grabs, and a depth-tested
    // disc is cut in half wherever the surface passes near its point. The net's lines still
    // show what lies behind the surface.
    glDisable(GL_DEPTH_TEST);
    glUniform1f(points_.uniform("u_alpha"), 1.0f);
    scene.net_points().draw(GL_POINTS);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
  }
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  gl::check_error("SceneRenderer::draw");
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
    if (i >= 0 && i < int(scene.surfaces().size())) scene.surfaces()[i].draw();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  gl::check_error("SceneRenderer::draw_tint");
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
  const float c[4] = {color[0], color[1], color[2], color[3]};
  draw_lines(lines, vp, v, c, width * float(v.pixel_scale), show_hidden);
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
  draw_lines(combs.teeth, vp, v, {0.00f, 0.55f, 0.50f, 0.55f}, 1.0f * s, true, offset_scale,
             offset_max, own_only ? combs.own_teeth : -1);
  draw_lines(combs.envelope, vp, v, {0.00f, 0.45f, 0.40f, 0.95f}, 1.8f * s, true, offset_scale,
             offset_max, own_only ? combs.own_envelope : -1);
}

void SceneRenderer::draw_lines(const GpuPrimitives& lines, const glm::mat4& vp, const Viewport& v,
                               const float (&color)[4], float width, bool show_hidden,
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
    glUniform4f(lines_.uniform("u_color"), color[0], color[1], color[2], color[3] * kHiddenAlpha);
    lines.draw(GL_LINES, count);
    glDepthFunc(GL_LEQUAL);
  }
  glUniform4f(lines_.uniform("u_color"), color[0], color[1], color[2], color[3]);
  lines.draw(GL_LINES, count);
  glDepthMask(GL_TRUE);
}

}  // namespace pl
