// The key of the control net's symbols: one row per point style (a kind as an editable, filled,
// or a derived, hollow point) and per arrow kind, each with its name. The symbols are drawn by the
// renderer's own shaders, so the key is exactly what the scene shows; the labels are burned in
// with the label font on an opaque panel. The editor's help shows it; exported pictures with the
// control net carry the entries their scenes use. Needs a current context to render.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/image.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

// "boundary", "inner", "twin", "central", "curve".
const char* point_kind_name(ControlPointKind kind);

// Entries as bit sets: bit point_style_tag(kind, role) of the point styles, bit ArrowKind of the
// arrow kinds (GpuScene::point_styles and arrow_kinds give a scene's).
struct PointKeyEntries {
  uint32_t point_styles = 0;
  uint32_t arrow_kinds = 0;
  bool empty() const { return point_styles == 0 && arrow_kinds == 0; }
  // Every kind in both roles (curve and free interior points editable only: they are the user's),
  // both arrow kinds.
  static PointKeyEntries all();
  static PointKeyEntries of(const DrawScene& scene);
  PointKeyEntries& operator|=(const PointKeyEntries& o) {
    point_styles |= o.point_styles;
    arrow_kinds |= o.arrow_kinds;
    return *this;
  }
};

// The key's rows and size in pixels. `scale` is the text's UI scale (text.hpp), `pixel_scale` the
// symbols' (the renderer's Viewport::pixel_scale: symbols are the size the scene draws them).
struct PointKeyLayout {
  struct Row {
    std::string label;
    int kind = -1;   // ControlPointKind of a point row, -1 for an arrow row
    int arrow = -1;  // ArrowKind of an arrow row
    PointRole role = PointRole::Editable;
  };
  std::vector<Row> rows;
  double scale = 1, pixel_scale = 1;
  int width = 0, height = 0;
  int pad = 0, row_height = 0, symbol_width = 0, label_x = 0;
};
PointKeyLayout point_key_layout(const PointKeyEntries& entries, double scale, double pixel_scale);

// The key as an image (opaque rounded panel; transparent outside its corners). Empty when there
// are no entries.
Image render_point_key(const SceneRenderer& renderer, const PointKeyLayout& layout);

// Blends `over` onto `image` with its top-left corner at (x, y).
void blend_image(Image& image, const Image& over, int x, int y);

}  // namespace pl
