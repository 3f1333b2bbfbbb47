#include "app/editor/screenshot.hpp"

#include <algorithm>
#include <stdexcept>

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
  for (int i = 0; i < n; ++i) {
    const int x0 = r.width * i / n, x1 = r.width * (i + 1) / n;
    Viewport v{x0, 0, x1 - x0, r.height, std::max(0.5, r.height / kReferenceHeight)};
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
      draw_text(image, r.width * i / n + 8 * scale, 8 * scale, r.panels[i].label, scale + 1,
                {0.13f, 0.14f, 0.17f});
  if (!r.legend_title.empty()) draw_legend(image, r.legend_range, r.legend_title, scale);
  return image;
}

}  // namespace pl
