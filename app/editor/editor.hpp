// The editor: a document, its live evaluations (the scene's own filling, and Gregory vs GB for
// the comparison), the camera and the selection, drawn with the renderer into a GLFW window with
// a Dear ImGui interface. The methods are spread over one file per job: editor.cpp (main loop,
// document lifetime), editor_input.cpp (mouse and keys), editor_viewport.cpp (drawing the
// views and their overlays), editor_panels.cpp (menus, side panel, status bar, help),
// editor_files.cpp (open/save/import/export, modals), drag_benchmark.cpp.
#pragma once

#include <chrono>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/document/document.hpp"
#include "app/editor/evaluated_view.hpp"
#include "app/editor/file_browser.hpp"
#include "app/editor/gl_window.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "app/editor/logic/view_math.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

struct EditorOptions {
  std::optional<std::filesystem::path> file;
  bool bench_drag = false;
  std::optional<PointRef> debug_point;  // print its window position once the view is shown
  int width = 1440, height = 900;
  bool compare = false;                             // start split: Gregory | GB
  std::optional<std::filesystem::path> screenshot;  // write one, then quit (scripts, docs)
};

class Editor {
 public:
  Editor(GlWindow& window, EditorOptions options);
  ~Editor();
  void load(Document doc) { set_document(std::move(doc)); }
  int run();                 // the interactive loop; returns the exit code
  int run_drag_benchmark();  // drag_benchmark.cpp

 private:
  using Clock = std::chrono::steady_clock;

  // editor.cpp
  void frame();
  void set_document(Document doc);
  void rebuild_views();
  void follow_document();
  void update_title();
  void show_error(const std::string& title, const std::string& message);
  void report_debug_point();
  void save_preferences_now();
  // Runs `action` now, or after asking when there are unsaved changes.
  void confirm_discard(const std::string& what, std::function<void()> action);

  // editor_input.cpp
  void handle_shortcuts();
  void handle_ctrl_key(int key, bool shift);
  void handle_viewport_mouse();
  void begin_point_drag(const ViewRect& rect);
  void nudge_selection(const Vec3& direction);
  void frame_all();
  void frame_selection();
  void set_preset(ViewPreset preset);
  Vec3 orbit_pivot() const;
  std::optional<Vec3> held_axis() const;

  // editor_viewport.cpp
  void draw_viewport();
  void draw_overlays(const ViewRect& rect, const EvaluatedView& view);
  void draw_legend(const ViewRect& rect, const ColorRange& range, const std::string& title);
  ColorRange current_range() const;
  ViewRect viewport_rect() const;  // the window area left for the 3D view
  std::vector<ViewRect> panel_rects() const;
  const EvaluatedView& panel_view(int panel) const;
  int panel_at(const Vec2& pixel) const;
  void refresh_difference();

  // editor_panels.cpp
  void draw_menu_bar();
  void draw_side_panel();
  void draw_display_section();
  void draw_selection_section();
  void draw_continuity_section();
  void draw_comparison_section();
  void draw_status_bar();
  void draw_help_window();
  void draw_probe_window();

  // editor_files.cpp
  void open_file(const std::filesystem::path& path);
  void save();
  void save_as(const std::filesystem::path& path);
  void export_mesh(const std::filesystem::path& path);
  void take_screenshot(const std::filesystem::path& path);
  void draw_file_dialogs();
  void draw_modals();
  void handle_drops();
  std::filesystem::path browse_start_dir() const;

  GlWindow& window_;
  EditorOptions options_;
  Preferences prefs_;
  std::optional<std::filesystem::path> prefs_file_;
  Document doc_;
  SceneRenderer renderer_;
  std::unique_ptr<EvaluatedView> main_view_;
  std::unique_ptr<EvaluatedView> compare_views_[2];  // Gregory, GB
  std::string view_error_;  // why the scene could not be evaluated (drawn instead of it)

  Camera camera_;
  bool camera_framed_ = false;
  bool compare_ = false;
  bool difference_ = false;
  std::unique_ptr<GpuScene> difference_gpu_;
  double difference_max_ = 0;
  uint64_t difference_revision_ = UINT64_MAX;

  // Selection and interaction.
  std::vector<PointRef> selection_;
  std::optional<PointRef> hover_;
  int hover_derived_ = -1;  // index of a hovered derived point (tooltip only)
  bool point_drag_ = false;
  DragMotion drag_motion_;
  ViewRect drag_rect_;
  std::vector<Vec3> drag_start_positions_, drag_last_positions_;
  enum class CameraDrag { None, Orbit, Pan } camera_drag_ = CameraDrag::None;
  Vec3 orbit_pivot_at_press_{0.0};
  bool clear_on_click_ = false;
  std::optional<ProbeHit> probe_;

  // Continuity figures of the fine evaluation (recomputed when it changes, not while dragging).
  SceneReport report_;
  uint64_t report_revision_ = UINT64_MAX;
  int worst_edge_ = -1;        // index into report_.edges
  int highlighted_edge_ = -1;  // network edge picked in the table

  // Timing.
  Clock::time_point last_frame_;
  std::deque<double> frame_ms_;
  double last_eval_ms_ = 0;
  std::optional<Clock::time_point> release_time_;  // waiting for the fine surfaces
  double last_settle_ms_ = 0;

  // Dialogs and messages.
  FileBrowser browser_;
  enum class BrowseFor { Open, SaveAs, ExportMesh, Screenshot } browse_for_ = BrowseFor::Open;
  std::string error_title_, error_message_;
  bool error_pending_ = false;
  std::string confirm_what_;
  std::function<void()> confirm_action_;
  bool confirm_pending_ = false;
  bool quit_ = false;
  bool show_help_ = false;
  bool show_screenshot_ = false;
  std::string status_message_;
  Clock::time_point status_time_;
  std::vector<std::string> dropped_;
  // Key presses since the last frame (key, mods): ImGui 1.86 keeps only the key state, so a press
  // and release between two frames (xdotool, a fast typist) would be lost.
  std::vector<std::pair<int, int>> key_presses_;
  bool debug_point_reported_ = false;
  int frames_ = 0;
  std::string shown_title_;
  float ui_scale_ = 1;
};

}  // namespace pl
