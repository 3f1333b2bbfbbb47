#include "render/point_key.hpp"

#include <algorithm>
#include <cmath>

#include "render/gpu_scene.hpp"
#include "render/offscreen_target.hpp"
#include "render/palette.hpp"
#include "render/text.hpp"

namespace pl {

namespace {

constexpr const char* kArrowNames[2] = {"tangent", "twist"};

bool has(uint32_t bits, int bit) {
  return (bits >> bit) & 1u;
}

}  // namespace

const char* point_kind_name(ControlPointKind kind) {
  static constexpr const char* kNames[] = {"boundary", "inner", "twin",
                                           "central",  "curve", "free interior"};
  static_assert(std::size(kNames) == palette::kPointKinds.size());
  const auto k = static_cast<std::size_t>(kind);
  return k < std::size(kNames) ? kNames[k] : "?";
}

PointKeyEntries PointKeyEntries::all() {
  uint32_t styles = 0;
  for (const PointRole role : {PointRole::Editable, PointRole::Derived})
    for (std::size_t kind = 0; kind < palette::kPointKinds.size(); ++kind)
      // Curve points and free interior points are always the user's: never derived.
      if (role == PointRole::Editable || (ControlPointKind(kind) != ControlPointKind::Curve &&
                                          ControlPointKind(kind) != ControlPointKind::FreeInterior))
        styles |= 1u << point_style_tag(ControlPointKind(kind), role);
  return {styles, 0x3u};
}

PointKeyEntries PointKeyEntries::of(const DrawScene& scene) {
  return {point_style_bits(scene.net), arrow_kind_bits(scene.arrows)};
}

PointKeyLayout point_key_layout(const PointKeyEntries& e, double scale, double pixel_scale) {
  PointKeyLayout k;
  k.scale = scale;
  k.pixel_scale = pixel_scale;
  for (const PointRole role : {PointRole::Editable, PointRole::Derived})
    for (int kind = 0; kind < int(palette::kPointKinds.size()); ++kind)
      if (has(e.point_styles, point_style_tag(ControlPointKind(kind), role)))
        k.rows.push_back({std::string(point_kind_name(ControlPointKind(kind))) +
                              (role == PointRole::Derived ? ", derived" : ""),
                          kind, -1, role});
  for (int arrow = 0; arrow < 2; ++arrow)
    if (has(e.arrow_kinds, arrow)) k.rows.push_back({kArrowNames[arrow], -1, arrow});
  if (k.rows.empty()) return k;
  auto px = [&](double units) { return static_cast<int>(std::lround(units * scale)); };
  k.pad = px(7);
  const double symbol = kPointSize * pixel_scale;
  k.row_height = std::max(px(17), static_cast<int>(std::ceil(1.6 * symbol)));
  // The symbol column: a point, or an arrow as long as its head and a bit of shaft.
  k.symbol_width = std::max(px(12), static_cast<int>(std::ceil(1.8 * symbol)));
  if (e.arrow_kinds)
    k.symbol_width =
        std::max(k.symbol_width, static_cast<int>(std::ceil(2.6 * kArrowHead * pixel_scale)));
  k.label_x = k.pad + k.symbol_width + px(6);
  int label_w = 0;
  for (const auto& r : k.rows) label_w = std::max(label_w, text_width(r.label, scale));
  k.width = k.label_x + label_w + k.pad;
  k.height = 2 * k.pad + static_cast<int>(k.rows.size()) * k.row_height;
  return k;
}

Image render_point_key(const SceneRenderer& renderer, const PointKeyLayout& k) {
  if (k.rows.empty()) return Image();
  // The symbols: a scene in pixel coordinates (x right, y up) seen from above, orthographic.
  DrawScene d;
  auto centre_y = [&](std::size_t row) {
    return k.pad + (static_cast<double>(row) + 0.5) * k.row_height;  // from the top
  };
  for (std::size_t i = 0; i < k.rows.size(); ++i) {
    const auto& r = k.rows[i];
    const double y = k.height - centre_y(i);
    const double symbol_x = k.pad + 0.5 * k.symbol_width;
    if (r.kind >= 0) {
      d.net.points.emplace_back(symbol_x, y, 0.0);
      d.net.kinds.push_back(ControlPointKind(r.kind));
      d.net.roles.push_back(r.role);
    } else {
      d.arrows.push_back(
          {{k.pad + 1.0, y, 0.0}, {k.pad + k.symbol_width - 1.0, y, 0.0}, ArrowKind(r.arrow)});
    }
  }
  const GpuScene gpu(d);
  Camera camera;
  camera.orthographic = true;
  camera.pitch = 1.5707963267948966;  // from +z: x right, y up
  camera.yaw = -1.5707963267948966;
  camera.target = Vec3(0.5 * k.width, 0.5 * k.height, 0.0);
  camera.distance = 0.5 * k.height / std::tan(0.5 * camera.fov_y);
  camera.scene_radius = std::max(k.width, k.height);
  DisplaySettings settings;
  settings.control_net = true;
  OffscreenTarget target(k.width, k.height);
  target.bind();
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  renderer.draw(gpu, camera, settings, ColorRange{}, {0, 0, k.width, k.height, k.pixel_scale});
  Image symbols(k.width, k.height);
  target.read_into(symbols, 0, 0);

  Image key(k.width, k.height);
  const int radius = static_cast<int>(std::lround(4 * k.scale));
  fill_rounded_rect(key, 0, 0, k.width, k.height, radius, palette::kPanel, 1.0f);
  stroke_rounded_rect(key, 0, 0, k.width, k.height, radius, std::max(1.0, 0.5 * k.scale),
                      palette::kPanelFrame, 1.0f);
  blend_image(key, symbols, 0, 0);
  for (std::size_t i = 0; i < k.rows.size(); ++i)
    draw_text(key, k.label_x, static_cast<int>(std::lround(centre_y(i))) - text_height(k.scale) / 2,
              k.rows[i].label, k.scale, palette::kInk);
  return key;
}

void blend_image(Image& image, const Image& over, int x, int y) {
  for (int r = 0; r < over.height; ++r)
    for (int c = 0; c < over.width; ++c) {
      const uint8_t* p = over.at(c, r);
      if (p[3] == 0) continue;
      image.blend(x + c, y + r, {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f}, p[3] / 255.0f);
    }
}

}  // namespace pl
