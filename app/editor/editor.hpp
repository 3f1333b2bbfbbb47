// The editor: it only composes its parts and runs the frame loop. Each part owns its state:
//   DocumentSession   the document, its file and the read-only sample folders  (logic)
//   SceneViews        the evaluated fillings shown and their GPU copies         (GL)
//   ViewNavigator     the camera and the orbit / pan / zoom gestures           (logic)
//   Selection         what is selected; ScenePicker what lies under the cursor (logic)
//   ToolBox           the active tool (select and drag; authoring tools)      (logic)
//   WorkPlane         where tools place new points, drawn as a grid          (logic)
//   ContinuityMonitor the Continuity panel's figures                        (logic)
//   ActionRegistry    every command: menus, context menu, keys, F1          (logic)
//   StatusLine        status-bar figures and messages                       (logic)
//   FileDialogs       file browser and modal questions                      (GUI)
//   ViewportPainter   highlights, grid and overlays over the 3D view        (GL)
// The methods below are the glue, one file per job: editor.cpp (loop, document lifetime),
// editor_actions.cpp (the action table), editor_input.cpp (keys and mouse to actions, tools
// and gestures), editor_authoring.cpp (the selection and tools following structural edits, tool
// feedback, renaming), editor_files.cpp (open, save, export, screenshot), editor_debug.cpp
// (what scripts and tests read back), drag_benchmark.cpp, pick_benchmark.cpp.
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/editor/editor_windows.hpp"
#include "app/editor/file_dialogs.hpp"
#include "app/editor/gl_window.hpp"
#include "app/editor/logic/actions.hpp"
#include "app/editor/logic/autosave.hpp"
#include "app/editor/logic/cad_export_job.hpp"
#include "app/editor/logic/compare_figures.hpp"
#include "app/editor/logic/continuity_monitor.hpp"
#include "app/editor/logic/curve_marks.hpp"
#include "app/editor/logic/document_session.hpp"
#include "app/editor/logic/editor_layout.hpp"
#include "app/editor/logic/preferences.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/status_line.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "app/editor/logic/tool.hpp"
#include "app/editor/logic/view_navigator.hpp"
#include "app/editor/rename_popup.hpp"
#include "app/editor/scene_views.hpp"
#include "app/editor/viewport_painter.hpp"
#include "render/scene_renderer.hpp"

namespace pl {

struct EditorOptions {
  std::optional<std::filesystem::path> file;
  bool bench_drag = false;
  bool bench_pick = false;
  // Objects whose window position is printed once the view is shown ("vertex 2", "face 1",
  // "edge 3"); with any, selection changes, context-menu items and saves are printed too.
  std::vector<SelectionItem> debug_items;
  // Print the editor's state at rest after every change (document counts, where every vertex,
  // edge, face and normal knob is on screen, the view's projection, pointer presses, status
  // messages): what the authoring end-to-end test waits for and clicks on.
  bool debug_state = false;
  int width = 1440, height = 900;
  bool compare = false;         // start split: Gregory | GB
  bool difference = false;      // and GB coloured by its distance to Gregory (implies compare)
  std::string compare_schemes;  // the panes' schemes ("gregory,gb,..."), the first the base
  std::optional<std::filesystem::path> screenshot;  // write one, then quit (scripts, docs)
};

class Editor {
 public:
  // `session` holds the startup document: a file the user named, the default scene (an
  // untitled copy) or a benchmark scene.
  Editor(GlWindow& window, EditorOptions options, DocumentSession session);
  ~Editor();
  int run();                 // the interactive loop; returns the exit code
  int run_drag_benchmark();  // drag_benchmark.cpp

 private:
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

  // editor.cpp
  void frame();
  void follow_document();
  // The objects whose control points are shown whatever their size on screen.
  NetFocus net_focus() const;
  void after_document_replaced();
  void rebuild_views(bool compare);
  void update_title();
  EditorLayout layout() const;
  Box scene_box() const;
  PickScene pick_scene(int panel, std::vector<SelectionItem>& items) const;
  ToolContext tool_context();
  void set_compare(bool on);
  // The comparison's figures table: asked for once the panes settle (compare_figures.hpp).
  void follow_figures();
  uint64_t doc_revision() const;

  // editor_actions.cpp
  void register_actions();

  // editor_authoring.cpp
  void follow_structure();
  void draw_tool_feedback();
  void start_rename();
  void draw_rename();

  // editor_input.cpp
  void handle_keys();
  bool takes_shortcuts() const;
  void handle_mouse();
  PointerEvent pointer_event(const ViewRect& rect, const PickResult* under) const;
  std::optional<Vec3> held_axis() const;
  Vec3 orbit_pivot() const;
  void nudge_selection(const KeyChord& chord);
  void escape();

  // editor_files.cpp
  void new_scene();
  void open_file(const std::filesystem::path& path);
  void save();  // Save, or Save As for an untitled document
  // Saves to the document's file and returns true (errors shown), or returns false when it
  // cannot (untitled, or a .gbp that no longer holds the scene): Save As is needed.
  bool save_in_place();
  FileDialogs::Handlers file_dialog_handlers();
  void save_as(const std::filesystem::path& path);
  void browse_save_as();  // Save As in the document's folder, with its name
  // A mesh (.obj .ply .off .stl) at once, or a CAD file (.step .stp .igs .iges) on a worker.
  void export_file(const std::filesystem::path& path);
  void take_screenshot(const std::filesystem::path& path);
  void handle_drops();
  std::filesystem::path browse_start_dir() const;
  // Once a frame, inside the ImGui frame: the autosave while the scene is dirty, a finished
  // export's report, and the busy indicator of a running one.
  void files_frame();
  void offer_recovery();  // the next autosave a crash left, if any
  // The view a document opens with: it faces a single patch's front (default_camera), framed
  // on what each panel shows.
  void open_view();
  // The same direction, framed tightly on what the panels show at their aspect.
  void frame_shown();
  std::vector<const DrawScene*> shown_scenes() const;

  // editor_debug.cpp
  void report_debug_items();
  void report_selection_change();
  void report_menu_item(const std::string& label, float x0, float y0, float x1, float y1);
  // A side-panel button's centre, printed when it appears or moves.
  void report_panel_item(const std::string& label, float x0, float y0, float x1, float y1);
  void report_state();
  bool debugging() const { return !options_.debug_items.empty() || options_.debug_state; }

  // The menus, panels and windows, given the parts they show; `range` is the colour range shown.
  void draw_interface(const ColorRange& range);

  GlWindow& window_;
  EditorOptions options_;
  Preferences prefs_;
  std::optional<std::filesystem::path> prefs_file_;
  DocumentSession session_;
  uint64_t session_serial_ = UINT64_MAX;  // the document the other parts were set up for
  uint64_t followed_revision_ = UINT64_MAX;
  SceneRenderer renderer_;
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
  FileDialogs dialogs_;
  Autosave autosave_;
  CadExportJob cad_job_;
  ViewportPainter painter_;
  CompareFigures figures_;
  PointKeyImage help_key_;  // F1's key of the control points' symbols
  Mouse mouse_;
  std::optional<ContextTarget> context_;           // the right-click menu is open on this
  std::optional<Clock::time_point> release_time_;  // waiting for the fine surfaces
  // What editor_debug.cpp has printed: the objects' positions, the last selection, and the
  // frames the context menu has been open (its items are printed once laid out).
  struct DebugState {
    bool positions = false;
    uint64_t selection = 0;
    int menu_frames = 0;
    std::string state;        // the last state report (printed again only when it changes)
    std::string message;      // the last status message printed
    bool text_input = false;  // a text field had the keyboard
    std::map<std::string, std::string> panel_items;  // label -> the line last printed
  } debug_;
  RenamePopup rename_;

  // Key presses since the last frame (key, mods): ImGui 1.86 keeps only the key state, so a press
  // and release between two frames (xdotool, a fast typist) would be lost. Dropped files too.
  std::vector<std::pair<int, int>> key_presses_;
  std::vector<std::string> dropped_;
  bool quit_ = false;
  bool show_help_ = false;
  bool show_curvature_graph_ = false;
  int frames_ = 0;
  int ready_frames_ = 0;  // frames since the views were last ready (a scene shown)
  // Since the process started: to the first frame swapped, and to the scene shown.
  std::optional<double> first_frame_ms_, loaded_ms_;
  std::string shown_title_;
  float ui_scale_ = 1;
};

}  // namespace pl
