// The editor's window: the shell around the EditorModel (logic/editor_model.hpp), which holds
// the document, the views, the camera, the selection, the tools and the actions. Each frame the
// shell measures the window, turns GLFW and ImGui input into the model's events (keys, the
// pointer, dropped files), lets the model follow the document, and draws what it holds: the 3D
// view (ViewportPainter), the menus, panels and windows (ImGui), and the dialogs the model asks
// for (FileDialogs; the shell is the model's EditorShell). GLFW is called here only.
// The methods below, one file per job: editor.cpp (loop, frame, interface), editor_input.cpp
// (GLFW and ImGui input to the model's events), editor_authoring.cpp (tool feedback, renaming),
// editor_files.cpp (dialogs, screenshots, the export's busy indicator), editor_debug.cpp (what
// scripts and tests read back), drag_benchmark.cpp.
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
#include "app/editor/logic/editor_model.hpp"
#include "app/editor/rename_popup.hpp"
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
  // --display MODE (with --bench-drag): the display the drag is measured in, in the render
  // command's syntax ("mean+isophotes+combs"): its base mode, curvature and isophote lines, and
  // the overlays it names on top of the defaults' (control net, network curves, borders).
  std::optional<std::string> display;
};

class Editor final : public EditorShell {
 public:
  // `session` holds the startup document: a file the user named, the default scene (an
  // untitled copy) or a benchmark scene.
  Editor(GlWindow& window, EditorOptions options, DocumentSession session);
  ~Editor() override;
  int run();                 // the interactive loop; returns the exit code
  int run_drag_benchmark();  // drag_benchmark.cpp

  // EditorShell: the dialogs and windows the model asks for (editor_files.cpp).
  void confirm_discard(const std::string& doing, std::function<void()> then) override;
  void ask_open() override;
  void ask_save_as() override;
  void ask_export() override;
  void ask_screenshot() override;
  void ask_name(const SelectionItem& item, const std::string& current) override;
  void show_error(const std::string& title, const std::string& message) override;
  void show_report(const std::string& title, const std::string& text) override;
  void offer_recovery(RecoveryOffer offer) override;
  void wake() override;

 private:
  using Clock = std::chrono::steady_clock;

  // editor.cpp
  void frame();
  void update_title();
  WindowMetrics metrics() const;
  // The menus, panels and windows; `range` is the colour range shown.
  void draw_interface(const ColorRange& range);

  // editor_input.cpp
  void send_keys();
  bool takes_shortcuts() const;
  PointerInput pointer_input() const;

  // editor_authoring.cpp
  void draw_tool_feedback();
  void draw_rename();

  // editor_files.cpp
  FileDialogs::Handlers file_dialog_handlers();
  void take_screenshot(const std::filesystem::path& path);
  void files_frame();  // the export's busy indicator and the model's file ticks

  // editor_debug.cpp
  void report_debug_items();
  void report_selection_change();
  void report_menu_item(const std::string& label, float x0, float y0, float x1, float y1);
  // A side-panel button's centre, printed when it appears or moves.
  void report_panel_item(const std::string& label, float x0, float y0, float x1, float y1);
  void report_state();
  bool debugging() const { return !options_.debug_items.empty() || options_.debug_state; }

  GlWindow& window_;
  EditorOptions options_;
  std::optional<std::filesystem::path> prefs_file_;
  float ui_scale_ = 1;
  EditorModel model_;
  SceneRenderer renderer_;
  FileDialogs dialogs_;
  ViewportPainter painter_;
  PointKeyImage help_key_;       // F1's key of the control points' symbols
  uint64_t context_serial_ = 0;  // the context menu last opened
  // The flag of the window that had the keyboard focus last frame (F1's help, the curvature
  // graph), or null: Esc clears it, closing that window, instead of reaching the model.
  bool* esc_closes_ = nullptr;
  // What editor_debug.cpp has printed: the objects' positions, the last selection, and the
  // frames the context menu has been open (its items are printed once laid out).
  struct DebugState {
    bool positions = false;
    uint64_t selection = 0;
    int menu_frames = 0;
    std::string state;        // the last state report (printed again only when it changes)
    std::string message;      // the last status message printed
    bool text_input = false;  // a text field had the keyboard
    bool help = false, help_focused = false;         // F1's window shown, with the keyboard focus
    std::map<std::string, std::string> panel_items;  // label -> the line last printed
  } debug_;
  RenamePopup rename_;

  // Key presses since the last frame (key, mods): ImGui 1.86 keeps only the key state, so a press
  // and release between two frames (xdotool, a fast typist) would be lost. Dropped files too.
  std::vector<std::pair<int, int>> key_presses_;
  std::vector<std::string> dropped_;
  int frames_ = 0;
  int ready_frames_ = 0;  // frames since the views were last ready (a scene shown)
  // Since the process started: to the first frame swapped, and to the scene shown.
  std::optional<double> first_frame_ms_, loaded_ms_;
  std::string shown_title_;
};

}  // namespace pl
