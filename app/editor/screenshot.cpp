#include "app/editor/screenshot.hpp"

#include <algorithm>
#include <stdexcept>

#include "app/editor/logic/compare_layout.hpp"
#include "render/legend.hpp"
#include "render/offscreen_target.hpp"
#include "render/text.hpp"

namespace pl {

namespace {
// Line widths and point sizes of the renderer are designed for this image height.
constexpr double kReferenceHeight = 1000.0;
}  // namespace

Image render_screenshot(const SceneRenderer& renderer, const ShotRequest& r) {
  if (r.panels.empty() || r.width < 1 || r.height < 1)
    throw std::runtime_error("nothing to render");
  const int max = OffscreenTarget::max_size();
  if (r.width > max || r.height > max)
    throw std::runtime_error("the driver allows at most " + std::to_string(max) + " pixels a side");
  OffscreenTarget target(r.width, r.height);
  target.bind();
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const int n = static_cast<int>(r.panels.size());
  // The panes as the window lays them out (rows of up to three), top-left origin.
  const std::vector<ViewRect> rects = pane_rects({0, 0, double(r.width), double(r.height)}, n);
  for (int i = 0; i < n; ++i) {
    const ViewRect& p = rects[i];
    Viewport v{int(p.x), int(r.height - p.y - p.height), int(p.width), int(p.height),
               std::max(0.5, p.height / kReferenceHeight)};
    DisplaySettings s = r.panels[i].settings;
    s.transparent = r.transparent;
    glEnable(GL_SCISSOR_TEST);
    glScissor(v.x, v.y, v.width, v.height);
    if (!r.transparent) renderer.draw_backdrop(v);
    renderer.draw(*r.panels[i].scene, r.camera, s, r.panels[i].range, v);
    glDisable(GL_SCISSOR_TEST);
  }
  Image image(r.width, r.height);
  target.read_into(image, 0, 0);
  const int scale = legend_scale(r.width, r.height);
  for (int i = 0; i < n; ++i)
    if (!r.panels[i].label.empty())
      draw_text(image, int(rects[i].x) + 8 * scale, int(rects[i].y) + 8 * scale, r.panels[i].label,
                scale + 1, {0.13f, 0.14f, 0.17f});
  draw_legends(image, r.legends, scale);
  return image;
}

}  // namespace pl
