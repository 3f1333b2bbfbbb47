#include "app/editor/editor.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "app/editor/action_menus.hpp"
#include "app/editor/curvature_graph_window.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/figures_table.hpp"
#include "app/editor/gpu_view_copy.hpp"
#include "app/editor/logic/curve_actions.hpp"
#include "app/editor/logic/editor_paths.hpp"
#include "app/editor/logic/launch_time.hpp"
#include "app/editor/side_panel.hpp"
#include "render/display_settings.hpp"

namespace pl {

namespace {

// How long the loop sleeps waiting for input when nothing animates (a tool should not spin a
// core while idle); short enough that a release's fine surfaces appear at once anyway.
constexpr double kIdleWaitSeconds = 0.25;
// While a scene is evaluated behind the progress bar: repaint often enough to look alive.
constexpr double kLoadingFrameSeconds = 0.05;

}  // namespace

namespace {

EditorModelOptions model_options(const EditorOptions& o) {
  EditorModelOptions m;
  m.compare = o.compare;
  m.difference = o.difference;
  if (!o.bench_drag && !o.screenshot) m.autosave_dir = state_dir();
  m.report_saves = !o.debug_items.empty() || o.debug_state;
  return m;
}

// The user's preferences (the benchmark measures the defaults, whatever the user chose), with
// the schemes asked for on the command line.
Preferences startup_preferences(const EditorOptions& o,
                                const std::optional<std::filesystem::path>& file) {
  Preferences prefs = file && !o.bench_drag ? load_preferences(*file) : default_preferences();
  if (o.display) {
    const DisplaySettings mode = parse_display_mode(*o.display);  // checked by run_editor
    DisplaySettings& d = prefs.display;
    d.base = mode.base;
    d.curvature = mode.curvature;
    d.isophote_lines = mode.isophote_lines;
    d.isophotes_over_zebra = mode.isophotes_over_zebra;
    d.control_net = d.control_net || mode.control_net;
    d.network_curves = d.network_curves || mode.network_curves;
    d.borders = d.borders || mode.borders;
    d.combs = d.combs || mode.combs;
  }
  if (!o.compare_schemes.empty()) {
    prefs.compare_schemes = o.compare_schemes;
    // The first pane is the base.
    prefs.compare_base = scheme_keyword(compare_setup_from(o.compare_schemes, "").base);
  }
  return prefs;
}

std::optional<std::filesystem::path> preferences_file() {
  if (const auto dir = config_dir()) return *dir / "preferences.ini";
  return std::nullopt;
}

}  // namespace

Editor::Editor(GlWindow& window, EditorOptions options, DocumentSession session)
    : window_(window),
      options_(std::move(options)),
      prefs_file_(preferences_file()),
      model_(model_options(options_), std::move(session),
             startup_preferences(options_, prefs_file_), *this, gpu_view_copies()),
      dialogs_(file_dialog_handlers()) {
  ui_scale_ = window_.follow_ui_scale(model_.prefs().ui_scale);
  model_.offer_recovery();
  window_.on_drop([this](const std::string& path) { dropped_.push_back(path); });
  window_.on_key([this](int key, int mods) { key_presses_.emplace_back(key, mods); });
}

Editor::~Editor() {
  if (prefs_file_ && !options_.bench_drag) save_preferences(*prefs_file_, model_.prefs());
}

WindowMetrics Editor::metrics() const {
  const ImGuiIO& io = ImGui::GetIO();
  WindowMetrics m;
  m.display = Vec2(io.DisplaySize.x, io.DisplaySize.y);
  m.frame_height = ImGui::GetFrameHeight();
  m.line_height = ImGui::GetTextLineHeightWithSpacing();
  m.point_px = kPointSize * ui_scale_;
  m.ui_scale = ui_scale_;
  return m;
}

void Editor::update_title() {
  const std::string title = model_.session().title() + " - PatchLab";
  if (title != shown_title_) {
    window_.set_title(title);
    shown_title_ = title;
  }
}

int Editor::run() {
  while (!model_.quit_requested) {
    if (window_.take_close_request())
      dialogs_.confirm_discard("quit", [this] { model_.quit_requested = true; });
    // Sleep until input unless something is animating (a drag settling, the first frames, which
    // ImGui needs to lay its windows out, or a gesture).
    const bool busy = frames_ < 4 || model_.animating();
    if (model_.views().loading())
      window_.wait_events(
          kLoadingFrameSeconds);  // repaint the progress, leave the worker the cores
    else if (busy)
      window_.poll_events();
    else
      window_.wait_events(kIdleWaitSeconds);
    frame();
  }
  return 0;
}

void Editor::draw_interface(const ColorRange& range) {
  EditorModel& m = model_;
  SceneViews& views = m.views();
  draw_menu_bar(m.actions());
  const EditorLayout l = m.layout();
  ToolContext tools = m.tool_context();
  SidePanel panel{m, range, ui_scale_, &tools, {}};
  if (debugging())
    panel.item_probe = [this](const std::string& label, float x0, float y0, float x1, float y1) {
      report_panel_item(label, x0, y0, x1, y1);
    };
  if (draw_side_panel(panel, l.menu_height, l.status_height)) m.rebuild_views(views.compare());

  StatusFigures figures;
  figures.coarse = views.ready() && !views.settled();
  figures.selected = m.selection().size();
  figures.tool = m.tools().active().name();
  if (views.ready()) figures.drawing = views.panel(0).drawing_note();
  // First: what a moving view gave up is the news (the rest of the line may be cut).
  if (const std::string note = m.draw_budget().note(); !note.empty())
    figures.drawing = note + (figures.drawing.empty() ? "" : "; ") + figures.drawing;
  const EditorModel::Mouse& mouse = m.mouse();
  if (mouse.under.item) figures.under = describe(*mouse.under.item);
  if (m.work_plane().shown && mouse.panel >= 0) {
    const ImGuiIO& io = ImGui::GetIO();
    const Ray ray = window_ray(m.nav().camera(), l.panels(views.panels())[mouse.panel],
                               Vec2(io.MousePos.x, io.MousePos.y));
    if (const auto p = m.work_plane().hit(m.nav().camera(), ray)) {
      char b[128];
      std::snprintf(b, sizeof b, "%s plane %.4g %.4g %.4g", work_plane_name(m.work_plane().kind),
                    p->x, p->y, p->z);
      figures.plane = b;
    }
  }
  draw_status_bar(m.status(), figures, ui_scale_);

  if (views.ready()) draw_legend_column(l.legend_column(), m.legends(range), ui_scale_);
  if (views.ready() && views.panels() > 1)
    draw_figures_table(
        l.table_strip(), m.figures(),
        m.figures().busy() || m.figures().result_key().revision != m.doc().revision());
  if (m.prefs().show_probe && mouse.probe && views.ready()) {
    const auto& meshes = views.panel(mouse.panel).shown().draw().surfaces;
    const int s = mouse.probe->surface;
    std::optional<double> distance;
    if (const DifferenceField* field = views.difference_field(mouse.panel))
      distance = field->distance_at(*mouse.probe);
    draw_probe_window(*mouse.probe, s >= 0 && s < int(meshes.size()) ? meshes[s].name : "",
                      distance, ui_scale_);
  }
  // The window with the keyboard focus, if it is one Esc closes (send_keys, next frame).
  esc_closes_ = nullptr;
  if (m.show_help && draw_help_window(&m.show_help, m.actions(), help_key_, renderer_, ui_scale_))
    esc_closes_ = &m.show_help;
  if (m.show_curvature_graph &&
      draw_curvature_graph_window(&m.show_curvature_graph, m.doc().scene(),
                                  selected_curve(m.doc().scene(), m.selection()), ui_scale_))
    esc_closes_ = &m.show_curvature_graph;
  draw_rename();
  if (const auto& target = m.context_target()) {
    if (m.context_serial() != context_serial_) {
      context_serial_ = m.context_serial();
      open_context_menu();
      debug_.menu_frames = 0;
    }
    MenuItemProbe probe;
    // Reported once, on the third frame of the menu: ImGui lays a popup out while it is hidden
    // on its first frame and may move it on the second.
    if (debugging() && ++debug_.menu_frames == 3)
      probe = [this](const std::string& label, float x0, float y0, float x1, float y1) {
        report_menu_item(label, x0, y0, x1, y1);
      };
    if (!draw_context_menu(m.actions(), *target, probe)) m.close_context();
  }
  dialogs_.draw(m.prefs(), ui_scale_, views.compare(), m.doc().path().stem().string());
}

void Editor::frame() {
  const auto start = Clock::now();
  ui_scale_ = window_.follow_ui_scale(model_.prefs().ui_scale);  // the monitor's scale, followed
  window_.begin_frame();
  model_.set_metrics(metrics());
  // A document replaced last frame (a menu, a dialog) first resets the parts that held the old
  // one; so does one replaced by a dropped file or a key now.
  model_.follow_session();
  if (!dropped_.empty()) model_.drop(dropped_.front());  // one document at a time
  dropped_.clear();
  send_keys();
  model_.pointer(pointer_input());
  model_.update();
  if (!loaded_ms_) loaded_ms_ = model_.loaded_ms();
  SceneViews& views = model_.views();
  const EditorLayout l = model_.layout();
  ViewportFrame f;
  f.window = &window_;
  f.renderer = &renderer_;
  f.model = &model_;
  f.viewport = l.viewport();
  f.panels = l.panels(views.panels());
  f.ui_scale = ui_scale_;
  const ColorRange range = views.colour_range(model_.prefs().display, model_.doc().revision());
  painter_.paint(f, range);
  draw_tool_feedback();
  draw_interface(range);
  files_frame();
  update_title();
  window_.end_frame();
  if (!first_frame_ms_) first_frame_ms_ = ms_since_launch();
  key_presses_.clear();
  if (debugging()) report_selection_change();
  if (options_.debug_state) report_state();
  const auto now = Clock::now();
  // Settle time: from the release to the swap of the first frame showing the fine surfaces.
  auto& release = model_.release_time();
  if (release && views.settled()) {
    model_.status().settle_ms = std::chrono::duration<double, std::milli>(now - *release).count();
    release.reset();
  }
  // The work of a frame, not the idle wait for input before it.
  const double frame_ms = std::chrono::duration<double, std::milli>(now - start).count();
  model_.status().add_frame(frame_ms);
  model_.draw_budget().frame(frame_ms, model_.moving());
  ++frames_;
  ready_frames_ = views.ready() ? ready_frames_ + 1 : 0;
  // Report only once the layout is final (ImGui hides new windows on their first frame).
  if (ready_frames_ >= 3) report_debug_items();
  // A scene that cannot be shown is shot with its message.
  const bool failed = !views.ready() && !views.loading() && frames_ >= 3;
  if (options_.screenshot && (ready_frames_ == 3 || failed)) {
    take_screenshot(*options_.screenshot);
    model_.quit_requested = true;
  }
}

}  // namespace pl
