// Draws an uploaded scene into whatever framebuffer is bound (an offscreen target now, a GLFW
// window's default framebuffer in the editor). Needs a current OpenGL 3.3 core context; owns
// the programs and the colour map texture, not the scene.
#pragma once

#include <array>
#include <span>

#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/gl_objects.hpp"
#include "render/gpu_scene.hpp"
#include "render/palette.hpp"

namespace pl {

struct Viewport {
  int x = 0, y = 0, width = 1, height = 1;  // framebuffer pixels; may extend past it (tiling)
  // Line widths and point sizes are multiplied by this, so a 4096 px render looks like a
  // 1000 px one.
  double pixel_scale = 1.0;
};

// Sizes of the overlays in pixels at pixel_scale 1 (shared with the point key).
inline constexpr float kPointSize = 10.0f;          // an editable point's width
inline constexpr float kDerivedPointScale = 0.85f;  // a derived point's width, relative
inline constexpr float kArrowWidth = 1.8f, kArrowHead = 11.0f;
// How visible the parts behind a surface are: enough to read what is there, faint enough not to
// be taken for the visible part.
inline constexpr float kHiddenAlpha = 0.22f;
inline constexpr float kHiddenPointAlpha = 0.3f;
// Pulls overlay lines in front of the triangles they lie on (NDC depth): the triangles are chords
// of the curved surface, so a line sampled on the exact surface can sit slightly behind them.
inline constexpr float kOverlayDepthBias = 4e-4f;

// Whether the surfaces' colours carry values a legend reads (the curvature modes, and the
// distance colouring drawn with them): a tint over them would change what they say.
inline bool colours_carry_values(const DisplaySettings& s) {
  return s.base == BaseMode::Curvature;
}

// How draw_selection marks surfaces (the editor's selection, or what is under the cursor).
struct SelectionStyle {
  std::array<float, 4> tint{};  // RGBA over the surfaces, where the colours carry no values
  std::array<float, 4> line{};  // the outline (the surfaces' borders, edges)
  float line_width = 3.5f;      // pixels, times the viewport's pixel scale
  bool show_hidden = true;      // the outline's parts behind surfaces drawn faintly
};

class SceneRenderer {
 public:
  SceneRenderer();  // compiles the programs; throws std::runtime_error with the shader's log

  // Draws the surfaces and the overlays into `viewport` (the caller clears and draws the
  // backdrop). `range` is used by the curvature modes.
  void draw(const GpuScene& scene, const Camera& camera, const DisplaySettings& settings,
            const ColorRange& range, const Viewport& viewport) const;
  // The studio backdrop (a soft gradient) over `viewport`, without touching depth.
  void draw_backdrop(const Viewport& viewport) const;

  // Highlights over a scene just drawn with draw() and the same camera (the editor's selection):
  // the given surfaces of `scene` tinted with `color` (RGBA, blended; depth-tested, so what the
  // scene hides stays hidden). Indices outside the scene are ignored.
  void draw_tint(const GpuScene& scene, std::span<const int> surfaces, const Camera& camera,
                 const std::array<float, 4>& color, const Viewport& viewport) const;
  // The selection over a scene just drawn with draw() and the same camera and settings: the
  // given surfaces of `scene` tinted with style.tint unless the settings colour them by value
  // (colours_carry_values: there the tint would wash the colour map out and the legend would
  // read wrong values), then `outline` in style.line over a dark halo, so that it reads on any
  // colour. Depth-tested, as draw_tint and draw_guides.
  void draw_selection(const GpuScene& scene, std::span<const int> surfaces,
                      const GpuPrimitives& outline, const Camera& camera,
                      const DisplaySettings& settings, const SelectionStyle& style,
                      const Viewport& viewport) const;
  // Lines of one colour (highlighted curves, a work-plane grid) over the scene, `width` pixels
  // (times the viewport's pixel scale); with show_hidden their parts behind surfaces are drawn
  // faintly, as the control net's are.
  void draw_guides(const GpuPrimitives& lines, const Camera& camera,
                   const std::array<float, 4>& color, float width, bool show_hidden,
                   const Viewport& viewport) const;

 private:
  // offset_scale and offset_max place comb vertices (see line.vert.glsl); 0 for plain lines.
  // count: the first vertices only (all when negative).
  void draw_lines(const GpuPrimitives& lines, const glm::mat4& vp, const Viewport& v,
                  const Rgb& color, float alpha, float width, bool show_hidden,
                  float offset_scale = 0.0f, float offset_max = 0.0f, GLsizei count = -1) const;
  // The control net: lines, derivative arrows and points, each faded where a surface hides it.
  void draw_net(const GpuScene& scene, const Camera& camera, const glm::mat4& vp,
                const Viewport& v) const;
  // own_only: the combs' first own_teeth / own_envelope vertices (GpuCombs).
  void draw_combs(const GpuCombs& combs, bool own_only, const glm::mat4& vp, const Viewport& v,
                  float offset_scale, float offset_max) const;
  gl::Program surface_, lines_, points_, arrows_, backdrop_, tint_;
  gl::VertexArray empty_vao_;  // the backdrop has no attributes, but core profiles need a VAO
  gl::Texture color_map_;
};

}  // namespace pl
