#include "model_driver.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "app/editor/logic/plane_handles.hpp"
#include "app/editor/theme.hpp"

namespace pl::test {

namespace {

WindowMetrics theme_metrics(int width, int height) {
  WindowMetrics m;
  m.display = Vec2(width, height);
  m.frame_height = kUiFontPixels + 2 * kUiFramePadding[1];
  m.line_height = kUiFontPixels + kUiItemSpacing[1];
  m.point_px = 10;  // the renderer's point size at scale 1
  m.ui_scale = 1;
  return m;
}

// A coordinate as --debug-state prints it ("%.1f") and a script reads it back.
double printed_value(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.1f", v);
  return std::strtod(b, nullptr);
}

}  // namespace

TempDir::TempDir(const std::string& name)
    : path_(std::filesystem::temp_directory_path() /
            ("patchlab-editor-model-" + name + "-" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

Vec2 whole_pixel(const Vec2& p) {
  return Vec2(std::nearbyint(p.x), std::nearbyint(p.y));  // the default mode: half to even
}

ModelDriver::ModelDriver(int width, int height, DocumentSession session,
                         EditorModelOptions options) {
  model_ =
      std::make_unique<EditorModel>(options, std::move(session), default_preferences(), shell_);
  shell_.dirty = [this] { return model_->doc().dirty(); };
  model_->set_metrics(theme_metrics(width, height));
  settle();
}

void ModelDriver::frame(const PointerInput& in) {
  model_->follow_session();
  model_->pointer(in);
  model_->update();
  model_->tick_files();
  // The window takes the settle time once the fine surfaces are shown.
  if (model_->release_time() && model_->views().settled()) model_->release_time().reset();
}

void ModelDriver::settle() {
  const auto start = std::chrono::steady_clock::now();
  PointerInput at_rest = pointer_;
  at_rest.pressed = {};
  // A few frames at least: the densities follow the sizes on screen a frame after a change.
  for (int frames = 0;; ++frames) {
    frame(at_rest);
    const SceneViews& v = model_->views();
    if (frames >= 3 && v.ready() && v.settled() && !model_->doc().dragging()) return;
    if (!v.ready() && !v.loading()) {
      ADD_FAILURE() << "the scene cannot be shown: " << v.error();
      return;
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(20)) {
      ADD_FAILURE() << "the model did not come to rest";
      return;
    }
    if (v.loading()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void ModelDriver::key(const std::string& name) {
  const auto chord = parse_chord(name);
  ASSERT_TRUE(chord) << name;
  model_->key(*chord);
  settle();
}

void ModelDriver::new_scene() {
  key("Ctrl+N");
  key("5");
}

void ModelDriver::move(const Vec2& pixel) {
  pointer_.pixel = whole_pixel(pixel);
  pointer_.pressed = {};
  frame(pointer_);
  settle();
}

void ModelDriver::press(const Vec2& pixel, int button) {
  move(pixel);
  pointer_.down[button] = true;
  pointer_.pressed = {};
  pointer_.pressed[button] = true;
  frame(pointer_);
  pointer_.pressed = {};
  // The press is seen; what it started (a drag, a gesture) runs until the release.
}

void ModelDriver::drag_to(const Vec2& pixel) {
  pointer_.pixel = whole_pixel(pixel);
  frame(pointer_);
}

void ModelDriver::release(int button) {
  pointer_.down[button] = false;
  frame(pointer_);
  settle();
}

void ModelDriver::click(const Vec2& pixel, int button) {
  press(pixel, button);
  release(button);
}

void ModelDriver::hold(bool shift, bool ctrl, bool alt) {
  pointer_.shift = shift, pointer_.ctrl = ctrl, pointer_.alt = alt;
}

ViewRect ModelDriver::view_rect() const {
  return model_->layout().panels(model_->views().panels())[0];
}

Vec2 ModelDriver::printed(const std::optional<Vec2>& p, const char* what) const {
  EXPECT_TRUE(p) << what << " is not on screen";
  if (!p) return Vec2(0.0);
  return Vec2(printed_value(p->x), printed_value(p->y));
}

std::optional<Vec2> ModelDriver::pick_pixel(const SelectionItem& item) {
  std::vector<SelectionItem> items;
  const PickScene scene = model_->pick_scene(0, items);
  const DisplaySettings& d = model_->prefs().display;
  return find_pixel_for(model_->picker(0), scene, model_->nav().camera(), view_rect(), item,
                        {d.control_net, d.network_curves});
}

Vec2 ModelDriver::vertex(int v) {
  const Network& net = *model_->doc().scene().network;
  return printed(project_to_window(model_->nav().camera(), view_rect(), net.vertices.at(v)),
                 "a vertex");
}

Vec2 ModelDriver::edge(int e) {
  return printed(pick_pixel(SelectionItem::edge(e)), "an edge");
}

Vec2 ModelDriver::face(int f) {
  return printed(pick_pixel(SelectionItem::face(f)), "a face");
}

Vec2 ModelDriver::curve(int c) {
  return printed(pick_pixel(SelectionItem::curve(c)), "a free curve");
}

Vec2 ModelDriver::knob(int v) {
  EditorModel& m = *model_;
  for (const PlaneHandle& h : plane_handles(m.doc().scene(), m.selection(), m.nav().camera(),
                                            view_rect(), m.metrics().ui_scale))
    if (h.vertex == v)
      return printed(project_to_window(m.nav().camera(), view_rect(), h.knob), "a knob");
  ADD_FAILURE() << "vertex " << v << " shows no knob";
  return Vec2(0.0);
}

Vec2 ModelDriver::world_to_pixel(const Vec3& p) {
  const Camera& camera = model_->nav().camera();
  const Vec2 o = printed(project_to_window(camera, view_rect(), Vec3(0)), "the origin");
  const Vec3 axes[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  double x = o.x, y = o.y;
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = printed(project_to_window(camera, view_rect(), axes[k]), "an axis");
    x += p[k] * (a.x - o.x);
    y += p[k] * (a.y - o.y);
  }
  return Vec2(x, y);
}

}  // namespace pl::test
