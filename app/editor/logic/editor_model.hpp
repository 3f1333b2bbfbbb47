// The editor without its window: the document session, what is shown (evaluated, with drawn
// copies only when a window asks for them), the camera, the selection, the tools, the work plane,
// the action table, the status line, the autosave and the comparison's figures, driven by
// events (the pointer as a frame saw it, a key chord, a dropped file, a file chosen in a
// dialog). The window shell (editor.hpp: GLFW, ImGui, the renderer) measures the window, turns
// its input into these events, draws what the model holds and answers what only a window can
// (dialogs, the help and graph windows) through EditorShell. Unit tests drive it with
// synthetic events and no display (tests/editor_model).
//
// The methods are spread by job: editor_model.cpp (parts, document lifetime, following the
// document), editor_model_input.cpp (pointer and keys to tools, gestures and actions),
// editor_model_actions.cpp (the action table), editor_model_files.cpp (new, open, save, export,
// drops, autosave and recovery).
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/autosave.hpp"
#include "app/editor/logic/cad_export_job.hpp"
#include "app/editor/logic/compare_figures.hpp"
#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/curve_marks.hpp"
#include "app/editor/logic/document_session.hpp"
#include "app/editor/logic/draw_budget.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/logic/editor_shell.hpp"
#include "app/editor/logic/export_formats.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/scene_views.hpp"
#include "app/editor/logic/status_line.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "app/editor/logic/tool.hpp"
#include "app/editor/logic/view_navigator.hpp"
#include "app/editor/logic/work_plane.hpp"

namespace pl {

struct EditorModelOptions {
  bool compare = false;     // the first document opens in the comparison
  bool difference = false;  // ... with the difference colouring
  // Where unsaved work is autosaved (none: no autosave, no recovery offered).
  std::optional<std::filesystem::path> autosave_dir;
  bool report_saves = false;  // print "saved PATH revision N" (scripts wait for it)
};

// What the window measured this frame.
struct WindowMetrics {
  Vec2 display{1280, 720};   // the window in pixels
  double frame_height = 19;  // a menu bar's height (ImGui's frame height)
  double line_height = 17;   // a line of text with its spacing (the figures table's rows)
  double point_px = 10;      // a drawn control point's width (the renderer's, times the scale)
  double ui_scale = 1;
};

// The pointer as one frame saw it.
struct PointerInput {
  Vec2 pixel{0.0};                // window pixels
  std::array<bool, 3> down{};     // left, right, middle held
  std::array<bool, 3> pressed{};  // ... went down this frame
  double wheel = 0;               // wheel steps this frame
  bool shift = false, ctrl = false, alt = false;
  std::optional<Vec3> axis;     // X, Y or Z held: motion along that axis
  bool over_interface = false;  // a panel, menu or dialog is under the cursor
};

class EditorModel {
 public:
  using Clock = std::chrono::steady_clock;

  // What the mouse is over and what the last press hit: the glue between the picker, the
  // navigator, the active tool and the context menu.
  struct Mouse {
    int panel = -1;      // view panel under the cursor, -1 if none
    PickResult under;    // what lies under the cursor this frame
    PickResult pressed;  // what lay under it at the last press (a click acts on it)
    int pressed_panel = -1;
    std::optional<Vec3> pressed_point;      // the world point under the last press, if any
    std::optional<Vec3> pressed_placement;  // where a new vertex would go at the last press
    bool tool_has_it = false;               // the active tool took the left press
    bool context_press = false;  // a right press that may end as a click: the context menu
    std::optional<ProbeHit> probe;
    uint64_t structure = 0;  // the network structure `under` and `pressed` were picked in
  };

  // `session` holds the startup document; `copies` makes the views' drawn copies (none: the
  // model draws nothing). The shell must outlive the model.
  EditorModel(EditorModelOptions options, DocumentSession session, Preferences prefs,
              EditorShell& shell, ViewCopyFactory copies = {});
  ~EditorModel();
  EditorModel(const EditorModel&) = delete;
  EditorModel& operator=(const EditorModel&) = delete;

  // --- Events, in a frame's order: metrics, drops, keys, the pointer, then update().
  void set_metrics(const WindowMetrics& metrics) { metrics_ = metrics; }
  // Resets the parts that held a document replaced since (a menu, a dialog): first in a frame.
  void follow_session();
  // Opens the file dropped on the window (asking first about unsaved changes).
  void drop(const std::filesystem::path& path);
  // Runs the action bound to the chord, then drops from the selection what it removed.
  void key(const KeyChord& chord);
  // Picks what is under the pointer and hands presses, drags and releases to the active tool
  // or the camera; a right click opens the context menu (context_target()).
  void pointer(const PointerInput& input);
  // Follows the document: the views, the densities for the sizes on screen, the continuity
  // figures, the selection after structural edits; frames a new document.
  void update();
  // Autosaves unsaved work and takes a finished CAD export's report (once a frame).
  void tick_files();

  // --- Files (the dialogs' answers come here).
  void new_scene();
  void open_file(const std::filesystem::path& path);
  // Save: in place, or asks the shell for a name when it cannot.
  void save();
  // Saves to the document's file and returns true (errors shown), or returns false when it
  // cannot (untitled, or a .gbp that no longer holds the scene): Save As is needed.
  bool save_in_place();
  void save_as(const std::filesystem::path& path);
  // A mesh (.obj .ply .off .stl) at once, or a CAD file (.step .stp .igs .iges) on a worker, in
  // the format chosen (File > Export As), else the one the extension names (export_target: a
  // name without an extension gets the chosen format's; a refusal is shown, nothing written).
  void export_file(const std::filesystem::path& path);
  // The format File > Export As chose for the export dialog's answer; null: File > Export...,
  // the typed extension decides.
  const ExportFormat* export_format() const { return export_format_; }
  std::filesystem::path browse_start_dir() const;
  // Where Save As opens, and the name typed in.
  std::pair<std::filesystem::path, std::string> save_as_start() const;
  // The name typed for a face or edge (F2); unchanged names make no undo step.
  void rename(const SelectionItem& item, const std::string& name);
  // The next autosave a crash left, if any, offered through the shell.
  void offer_recovery();

  // --- What the shell reads (and the side panel edits).
  DocumentSession& session() { return session_; }
  Document& doc() { return session_.doc(); }
  Preferences& prefs() { return prefs_; }
  SceneViews& views() { return views_; }
  ViewNavigator& nav() { return nav_; }
  Selection& selection() { return selection_; }
  ToolBox& tools() { return tools_; }
  WorkPlane& work_plane() { return work_plane_; }
  const ContinuityMonitor& continuity() const { return continuity_; }
  const CurveMarks& curve_marks() const { return curve_marks_; }
  ActionRegistry& actions() { return actions_; }
  StatusLine& status() { return status_; }
  CompareFigures& figures() { return figures_; }
  const CadExportJob& cad_job() const { return cad_job_; }
  const Mouse& mouse() const { return mouse_; }
  // The resolution the 3D view is drawn at while something moves; the window reports each
  // frame's time to it.
  DrawBudget& draw_budget() { return draw_budget_; }
  const WindowMetrics& metrics() const { return metrics_; }

  EditorLayout layout() const;
  // Whether any view shows a surface (the colour maps and their legends need one).
  bool shows_surfaces() const;
  // The legends of the view as shown, `curvature` the curvature colour range.
  std::vector<LegendSpec> legends(const ColorRange& curvature) const;
  Box scene_box() const;
  // What Frame All keeps in view: every point the views draw (framing_points) and, with combs
  // shown, the combs' tips as they are drawn (comb_tips).
  std::vector<Vec3> framing_points() const;
  PickScene pick_scene(int panel, std::vector<SelectionItem>& items) const;
  ScenePicker& picker(int panel) { return pickers_.at(std::size_t(panel)); }
  ToolContext tool_context();
  // The objects whose control points are shown whatever their size on screen.
  NetFocus net_focus() const;
  std::vector<const DrawScene*> shown_scenes() const;
  void set_compare(bool on);
  void rebuild_views(bool compare);

  // The right-click menu: what it was opened on (none while closed), and a serial that moves
  // each time one opens.
  const std::optional<ContextTarget>& context_target() const { return context_; }
  uint64_t context_serial() const { return context_serial_; }
  void close_context() { context_.reset(); }

  // A drag, a tool holding the pointer or a camera gesture is under way.
  bool moving() const;
  // ... or the fine surfaces are awaited after a release (the loop should not sleep).
  bool animating() const { return moving() || release_time_.has_value(); }
  // The time of the last release, until the fine surfaces are shown (settle time).
  std::optional<Clock::time_point>& release_time() { return release_time_; }
  // When the first evaluated scene was taken, in ms since the process's launch (the launch
  // figure editor_loaded_ms), if it was.
  std::optional<double> loaded_ms() const { return loaded_ms_; }

  // Windows and requests the actions switch.
  bool show_help = false;
  bool show_curvature_graph = false;
  bool quit_requested = false;

 private:
  // editor_model.cpp
  void after_document_replaced();
  void follow_figures();
  void follow_structure();
  void follow_continuity();
  void open_view();
  void frame_shown();

  // editor_model_actions.cpp: the table, one group at a time.
  void register_actions();
  void add_file_actions();
  void add_edit_actions();
  void add_object_actions();
  void add_view_actions();
  void add_work_plane_actions();
  void add_tool_actions();
  void start_rename();

  // editor_model_input.cpp
  PointerEvent pointer_event(const PointerInput& in, const ViewRect& rect,
                             const PickResult* under) const;
  void pointer_held(const PointerInput& in, const std::vector<ViewRect>& rects);
  void gesture(const PointerInput& in, const std::vector<ViewRect>& rects);
  void open_context_menu();
  Vec3 orbit_pivot() const;
  void nudge_selection(const KeyChord& chord);
  void escape();

  void say(const std::string& message) { status_.say(message); }

  EditorModelOptions options_;
  EditorShell& shell_;
  WindowMetrics metrics_;
  Preferences prefs_;
  DocumentSession session_;
  uint64_t session_serial_ = UINT64_MAX;  // the document the other parts were set up for
  uint64_t followed_revision_ = UINT64_MAX;
  SceneViews views_;
  ViewNavigator nav_;
  Selection selection_;
  std::array<ScenePicker, kMaxComparePanes> pickers_;  // one per panel: each its own filling
  ToolBox tools_;
  WorkPlane work_plane_;
  ContinuityMonitor continuity_;
  CurveMarks curve_marks_;  // knot ticks and joints of the free curves
  ActionRegistry actions_;
  StatusLine status_;
  Autosave autosave_;
  CadExportJob cad_job_;
  CompareFigures figures_;
  Mouse mouse_;
  DrawBudget draw_budget_;
  std::optional<ContextTarget> context_;  // the right-click menu is open on this
  uint64_t context_serial_ = 0;
  std::optional<Clock::time_point> release_time_;  // waiting for the fine surfaces
  const ExportFormat* export_format_ = nullptr;    // File > Export As's choice
  std::optional<double> loaded_ms_;
};

}  // namespace pl
