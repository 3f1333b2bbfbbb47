#include "app/editor/logic/view_navigator.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/default_view.hpp"

namespace pl {

void ViewNavigator::frame(const Box& box, double aspect) {
  camera_.frame(box.empty() ? empty_scene_box() : box, aspect);
  mark_framed();
}

void ViewNavigator::frame_all(std::span<const Vec3> points, double aspect) {
  if (points.empty()) {
    frame(Box(), aspect);
    return;
  }
  camera_.frame_points(points, aspect, kFrameMargin);
  if (!camera_.orthographic) {
    // frame_points scales the points about the target in depth too: a point beyond the target
    // would keep less than the margin. The distance at which each point's own projection keeps
    // it: |x| <= (distance + z) tan_h / margin, likewise for y.
    const double tan_v = std::tan(0.5 * camera_.fov_y), tan_h = tan_v * aspect;
    const Vec3 f = camera_.forward(), u = camera_.up(), r = camera_.right();
    double need = camera_.distance;
    for (const Vec3& p : points) {
      const Vec3 q = p - camera_.target;
      const double x = std::abs(glm::dot(q, r)), y = std::abs(glm::dot(q, u)), z = glm::dot(q, f);
      need = std::max({need, kFrameMargin * x / tan_h - z, kFrameMargin * y / tan_v - z});
    }
    camera_.distance = need;
  }
  mark_framed();
}

void ViewNavigator::frame_closely(const Box& box, double aspect) {
  if (box.empty()) return;
  const double keep_radius = camera_.scene_radius;
  Box grown = box;
  const double r = std::max(box.radius(), 0.08 * keep_radius);
  grown.add(box.centre() + Vec3(r));
  grown.add(box.centre() - Vec3(r));
  camera_.frame(grown, aspect);
  camera_.scene_radius = std::max(keep_radius, camera_.scene_radius);
  mark_framed();
}

void ViewNavigator::preset(ViewPreset p, const Box& scene, double aspect) {
  camera_ =
      preset_camera(p, scene.empty() ? empty_scene_box() : scene, aspect, camera_.orthographic);
  mark_framed();
}

void ViewNavigator::open_view(std::span<const DrawScene* const> scenes, double aspect) {
  const bool ortho = camera_.orthographic;
  if (framing_points(scenes).empty())
    camera_ = preset_camera(ViewPreset::Iso, empty_scene_box(), aspect, ortho);
  else
    camera_ = default_camera(scenes, aspect);
  camera_.orthographic = ortho;
  mark_framed();
}

void ViewNavigator::frame_tightly(std::span<const DrawScene* const> scenes, double aspect) {
  const std::vector<Vec3> points = framing_points(scenes);
  if (points.empty()) return;
  camera_.frame_points(points, aspect);
  mark_framed();
}

void ViewNavigator::follow_panel(const Vec2& window, int panes, double width) {
  const PanelShape was = std::exchange(panel_, PanelShape{window, panes, width});
  if (was.window == window && was.panes == panes && was.width > 0 && width > 0 &&
      was.width != width)
    camera_.zoom(width / was.width);
}

void ViewNavigator::begin(Gesture g, const Vec2& pixel, const Vec3& pivot,
                          std::vector<Vec3> model) {
  gesture_ = g;
  pivot_ = pivot;
  model_ = std::move(model);
  start_.reset();
  press_ = last_ = pixel;
  travel_ = 0;
}

void ViewNavigator::move(const Vec2& pixel, const ViewRect& rect) {
  if (gesture_ == Gesture::None) return;
  const Vec2 d = pixel - last_;
  last_ = pixel;
  travel_ = std::max(travel_, glm::length(pixel - press_));
  if (d == Vec2(0)) return;
  if (gesture_ == Gesture::Orbit) {
    // Where the model was when the orbit began: it never gets further out of place than that.
    if (!start_) start_ = screen_box(camera_, rect, model_);
    orbit_about(camera_, pivot_, -d.x * kOrbitRadiansPerPixel, d.y * kOrbitRadiansPerPixel);
    keep_in_view(camera_, rect, model_, *start_);
  } else
    pan_pixels(camera_, rect, d.x, d.y);
}

bool ViewNavigator::end() {
  const bool click = gesture_ != Gesture::None && travel_ < kClickSlopPx;
  gesture_ = Gesture::None;
  return click;
}

void ViewNavigator::wheel(const ViewRect& rect, const Vec2& pixel, double notches) {
  if (notches != 0) zoom_at(camera_, rect, pixel, std::pow(kWheelZoom, notches));
}

std::vector<Vec3> orbit_sample(std::span<const DrawScene* const> scenes, std::size_t most) {
  std::size_t total = 0;
  for (const DrawScene* s : scenes) {
    for (const SurfaceMesh& m : s->surfaces) total += m.positions.size();
    total += s->net.points.size();
    for (const auto& c : s->network_curves) total += c.size();
  }
  const std::size_t stride =
      std::max<std::size_t>(1, (total + most - 1) / std::max<std::size_t>(most, 1));
  std::vector<Vec3> out;
  out.reserve(total / stride + 1);
  std::size_t i = 0;
  auto take = [&](const Vec3& p) {
    if (i++ % stride == 0) out.push_back(p);
  };
  for (const DrawScene* s : scenes) {
    for (const SurfaceMesh& m : s->surfaces)
      for (const Vec3& p : m.positions) take(p);
    for (const Vec3& p : s->net.points) take(p);
    for (const auto& c : s->network_curves)
      for (const Vec3& p : c) take(p);
  }
  return out;
}

}  // namespace pl
