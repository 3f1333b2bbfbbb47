#include "app/editor/logic/view_navigator.hpp"

#include <algorithm>
#include <cmath>

#include "render/default_view.hpp"

namespace pl {

void ViewNavigator::frame(const Box& box, double aspect) {
  if (box.empty()) return;
  camera_.frame(box, aspect);
  framed_ = true;
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
  framed_ = true;
}

void ViewNavigator::preset(ViewPreset p, const Box& scene, double aspect) {
  if (scene.empty()) return;
  camera_ = preset_camera(p, scene, aspect, camera_.orthographic);
  framed_ = true;
}

void ViewNavigator::open_view(std::span<const DrawScene* const> scenes, double aspect) {
  const bool ortho = camera_.orthographic;
  if (framing_points(scenes).empty())
    camera_ = preset_camera(ViewPreset::Iso, Box{Vec3(-1), Vec3(1)}, aspect, ortho);
  else
    camera_ = default_camera(scenes, aspect);
  camera_.orthographic = ortho;
  framed_ = true;
}

void ViewNavigator::frame_tightly(std::span<const DrawScene* const> scenes, double aspect) {
  const std::vector<Vec3> points = framing_points(scenes);
  if (points.empty()) return;
  camera_.frame_points(points, aspect);
  framed_ = true;
}

void ViewNavigator::begin(Gesture g, const Vec2& pixel, const Vec3& pivot, const Box& scene) {
  gesture_ = g;
  pivot_ = pivot;
  keep_.reset();
  if (!scene.empty()) keep_ = scene.centre();
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
    const auto was = keep_ ? project_to_window(camera_, rect, *keep_) : std::nullopt;
    orbit_about(camera_, pivot_, -d.x * kOrbitRadiansPerPixel, d.y * kOrbitRadiansPerPixel);
    if (was) keep_in_view(camera_, rect, *keep_, *was);
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

}  // namespace pl
