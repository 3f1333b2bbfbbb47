#include "app/editor/editor.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <cstdio>
#include <iostream>

#include "app/editor/logic/editor_paths.hpp"
#include "core/base/data_error.hpp"

namespace pl {

namespace {

// How long the loop sleeps waiting for input when nothing animates (a tool should not spin a
// core while idle); short enough that a release's fine surfaces appear at once anyway.
constexpr double kIdleWaitSeconds = 0.25;
constexpr std::size_t kFrameHistory = 120;

}  // namespace

Editor::Editor(GlWindow& window, EditorOptions options)
    : window_(window), options_(std::move(options)) {
  if (const auto dir = config_dir()) prefs_file_ = *dir / "preferences.ini";
  prefs_ = prefs_file_ ? load_preferences(*prefs_file_) : default_preferences();
  ui_scale_ = prefs_.ui_scale > 0 ? static_cast<float>(prefs_.ui_scale) : window_.content_scale();
  window_.apply_ui_scale(ui_scale_);
  glfwSetWindowUserPointer(window_.handle(), this);
  glfwSetDropCallback(window_.handle(), [](GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<Editor*>(glfwGetWindowUserPointer(w));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
  });
  glfwSetKeyCallback(
      window_.handle(), [](GLFWwindow* w, int key, int scancode, int action, int mods) {
        ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);  // ImGui's state stays current
        auto* self = static_cast<Editor*>(glfwGetWindowUserPointer(w));
        if (action != GLFW_RELEASE) self->key_presses_.emplace_back(key, mods);
      });
  last_frame_ = Clock::now();
}

Editor::~Editor() {
  save_preferences_now();
}

void Editor::save_preferences_now() {
  if (prefs_file_ && !options_.bench_drag) save_preferences(*prefs_file_, prefs_);
}

void Editor::set_document(Document doc) {
  doc_ = std::move(doc);
  selection_.clear();
  hover_.reset();
  point_drag_ = false;
  camera_framed_ = false;
  report_revision_ = UINT64_MAX;
  difference_revision_ = UINT64_MAX;
  rebuild_views();
  update_title();
}

void Editor::rebuild_views() {
  if (options_.compare) {
    compare_ = true;
    options_.compare = false;
  }
  main_view_.reset();
  compare_views_[0].reset();
  compare_views_[1].reset();
  view_error_.clear();
  try {
    const bool combs = prefs_.display.combs;
    const int teeth = prefs_.display.comb_teeth;
    main_view_ = std::make_unique<EvaluatedView>(doc_, std::nullopt, prefs_.coarse_density,
                                                 prefs_.fine_density, combs, teeth);
    if (compare_ && doc_.scene().network) {
      compare_views_[0] = std::make_unique<EvaluatedView>(
          doc_, FaceScheme::Gregory, prefs_.coarse_density, prefs_.fine_density, combs, teeth);
      compare_views_[1] = std::make_unique<EvaluatedView>(
          doc_, FaceScheme::GB, prefs_.coarse_density, prefs_.fine_density, combs, teeth);
    }
  } catch (const DataError& e) {
    view_error_ = e.what();
  }
  if (compare_ && !compare_views_[0]) compare_ = false;
}

void Editor::follow_document() {
  const auto t0 = Clock::now();
  bool changed = false;
  try {
    // Combs turned on or off, or a new tooth count: the views resample their curves in follow()
    // (nothing is re-evaluated; no comb work while combs are off).
    const DisplaySettings& d = prefs_.display;
    if (main_view_) {
      main_view_->configure_combs(d.combs, d.comb_teeth);
      changed |= main_view_->follow(doc_);
    }
    if (compare_)
      for (auto& v : compare_views_)
        if (v) {
          v->configure_combs(d.combs, d.comb_teeth);
          changed |= v->follow(doc_);
        }
  } catch (const DataError& e) {
    status_message_ = e.what();
    status_time_ = Clock::now();
  }
  if (changed) last_eval_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  // Continuity figures follow the fine surfaces only: analysing every drag step would cost
  // more than the drag itself.
  if (main_view_ && main_view_->settled() && report_revision_ != doc_.revision()) {
    report_revision_ = doc_.revision();
    report_ = analyze_scene(doc_.scene(), main_view_->fine().surfaces());
    worst_edge_ = -1;
    for (std::size_t i = 0; i < report_.edges.size(); ++i)
      if (worst_edge_ < 0 ||
          report_.edges[i].max_normal_angle_deg > report_.edges[worst_edge_].max_normal_angle_deg)
        worst_edge_ = static_cast<int>(i);
  }
}

void Editor::update_title() {
  const std::string name =
      doc_.path().empty() ? std::string("untitled") : doc_.path().filename().string();
  const std::string title = name + (doc_.dirty() ? " *" : "") + " - PatchLab";
  if (title != shown_title_) {
    window_.set_title(title);
    shown_title_ = title;
  }
}

void Editor::show_error(const std::string& title, const std::string& message) {
  error_title_ = title;
  error_message_ = message;
  error_pending_ = true;
  std::cerr << "patchlab: " << message << "\n";
}

void Editor::confirm_discard(const std::string& what, std::function<void()> action) {
  if (!doc_.dirty()) {
    action();
    return;
  }
  confirm_what_ = what;
  confirm_action_ = std::move(action);
  confirm_pending_ = true;
}

void Editor::report_debug_point() {
  if (!options_.debug_point || debug_point_reported_ || !main_view_) return;
  const auto rects = panel_rects();
  if (!point_exists(doc_.scene(), *options_.debug_point)) {
    std::cout << "debug-point missing" << std::endl;
    debug_point_reported_ = true;
    return;
  }
  const Vec3 p = point_position(doc_.scene(), *options_.debug_point);
  const auto s = project_to_window(camera_, rects[0], p);
  if (!s) return;
  int wx = 0, wy = 0;
  glfwGetWindowPos(window_.handle(), &wx, &wy);
  const double wpp = world_per_pixel(camera_, rects[0], p);
  const Vec3 r = camera_.right(), u = camera_.up();
  std::printf(
      "debug-point %.3f %.3f window %d %d world-per-pixel %.17g right %.17g %.17g %.17g "
      "up %.17g %.17g %.17g\n",
      s->x, s->y, wx, wy, wpp, r.x, r.y, r.z, u.x, u.y, u.z);
  std::fflush(stdout);
  debug_point_reported_ = true;
}

int Editor::run() {
  while (!quit_) {
    if (glfwWindowShouldClose(window_.handle())) {
      glfwSetWindowShouldClose(window_.handle(), GLFW_FALSE);
      confirm_discard("quit", [this] { quit_ = true; });
    }
    // Sleep until input unless something is animating (a drag settling, the first frames, which
    // ImGui needs to lay its windows out, or a pending message).
    const bool busy = frames_ < 4 || release_time_ || doc_.dragging() || point_drag_ ||
                      camera_drag_ != CameraDrag::None;
    if (busy)
      glfwPollEvents();
    else
      glfwWaitEventsTimeout(kIdleWaitSeconds);
    frame();
  }
  return 0;
}

void Editor::frame() {
  const auto start = Clock::now();
  window_.begin_frame();
  handle_drops();
  handle_shortcuts();
  handle_viewport_mouse();
  follow_document();
  draw_viewport();
  draw_menu_bar();
  draw_side_panel();
  draw_status_bar();
  draw_probe_window();
  if (show_help_) draw_help_window();
  draw_file_dialogs();
  draw_modals();
  update_title();
  window_.end_frame();
  key_presses_.clear();
  const auto now = Clock::now();
  // Settle time: from the release to the swap of the first frame showing the fine surfaces.
  if (release_time_ && main_view_ && main_view_->settled()) {
    last_settle_ms_ = std::chrono::duration<double, std::milli>(now - *release_time_).count();
    release_time_.reset();
  }
  // The work of a frame, not the idle wait for input before it.
  frame_ms_.push_back(std::chrono::duration<double, std::milli>(now - start).count());
  if (frame_ms_.size() > kFrameHistory) frame_ms_.pop_front();
  last_frame_ = now;
  ++frames_;
  // Report only once the layout is final (ImGui hides new windows on their first frame).
  if (frames_ >= 3) report_debug_point();
  if (frames_ == 3 && options_.screenshot) {
    take_screenshot(*options_.screenshot);
    quit_ = true;
  }
}

}  // namespace pl
