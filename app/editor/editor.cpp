#include "app/editor/editor.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/editor/action_menus.hpp"
#include "app/editor/curvature_graph_window.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/figures_table.hpp"
#include "app/editor/logic/add_edge_tool.hpp"
#include "app/editor/logic/add_vertex_tool.hpp"
#include "app/editor/logic/curve_actions.hpp"
#include "app/editor/logic/editor_paths.hpp"
#include "app/editor/logic/launch_time.hpp"
#include "app/editor/logic/make_face_tool.hpp"
#include "app/editor/logic/new_curve_tool.hpp"
#include "app/editor/logic/select_tool.hpp"
#include "app/editor/logic/split_edge_tool.hpp"
#include "app/editor/side_panel.hpp"
#include "core/base/data_error.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

// How long the loop sleeps waiting for input when nothing animates (a tool should not spin a
// core while idle); short enough that a release's fine surfaces appear at once anyway.
constexpr double kIdleWaitSeconds = 0.25;
// While a scene is evaluated behind the progress bar: repaint often enough to look alive.
constexpr double kLoadingFrameSeconds = 0.05;

}  // namespace

Editor::Editor(GlWindow& window, EditorOptions options, DocumentSession session)
    : window_(window),
      options_(std::move(options)),
      session_(std::move(session)),
      dialogs_(file_dialog_handlers()),
      autosave_(options_.bench_drag || options_.screenshot ? std::nullopt : state_dir()) {
  if (const auto dir = config_dir()) prefs_file_ = *dir / "preferences.ini";
  // The benchmark measures the default settings, whatever the user chose.
  prefs_ =
      prefs_file_ && !options_.bench_drag ? load_preferences(*prefs_file_) : default_preferences();
  if (!options_.compare_schemes.empty()) {
    prefs_.compare_schemes = options_.compare_schemes;
    // The first pane is the base.
    prefs_.compare_base = scheme_keyword(compare_setup_from(options_.compare_schemes, "").base);
  }
  ui_scale_ = window_.follow_ui_scale(prefs_.ui_scale);
  tools_.add(std::make_unique<SelectTool>());
  tools_.add(std::make_unique<AddVertexTool>());
  tools_.add(std::make_unique<AddEdgeTool>());
  tools_.add(std::make_unique<MakeFaceTool>());
  tools_.add(std::make_unique<SplitEdgeTool>());
  tools_.add(std::make_unique<NewCurveTool>());
  register_actions();
  // A key given to two commands is a programmer's error: refuse to start (the end-to-end tests
  // start the editor, so they catch it).
  if (const auto clashes = actions_.conflicts(); !clashes.empty())
    throw std::logic_error("a key is bound to two commands: " + clashes.front());
  offer_recovery();
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
}

Editor::~Editor() {
  if (prefs_file_ && !options_.bench_drag) save_preferences(*prefs_file_, prefs_);
  autosave_.discard();  // a normal quit (a crash never gets here)
}

EditorLayout Editor::layout() const {
  const ImGuiIO& io = ImGui::GetIO();
  EditorLayout l{Vec2(io.DisplaySize.x, io.DisplaySize.y), ImGui::GetFrameHeight(),
                 ImGui::GetFrameHeight() + 6.0 * ui_scale_, ui_scale_};
  // The legends' column takes its width from the view, so no legend covers a panel.
  l.legends =
      int(view_legends(prefs_.display, views_.compare(), views_.difference, {-1, 1}, 1).size());
  // The comparison's figures under its panes: a row per face and scheme.
  if (views_.panels() > 1) {
    const auto& result = figures_.result();
    int rows = 0;
    if (result)
      for (const FaceFigures& f : result->faces) rows += int(f.schemes.size());
    l.table_height = figures_table_height(std::max(rows, 1), ui_scale_);
  }
  return l;
}

Box Editor::scene_box() const {
  return views_.ready() ? views_.panel(0).shown().draw().bounds() : Box();
}

PickScene Editor::pick_scene(int panel, std::vector<SelectionItem>& items) const {
  const LiveSurfaces& live = views_.panel(panel).shown();
  items = surface_items(live.surfaces());
  return {live.draw().surfaces, items, live.draw().network_curves, &live.points(),
          live.draw().free_curves};
}

ToolContext Editor::tool_context() {
  return {session_.doc(),
          selection_,
          nav_.camera(),
          work_plane_,
          [this](const std::string& m) { status_.say(m); },
          ui_scale_};
}

void Editor::after_document_replaced() {
  session_serial_ = session_.serial();
  ToolContext ctx = tool_context();
  tools_.active().cancel(ctx);
  selection_.clear();
  mouse_ = {};
  context_.reset();
  release_time_.reset();
  for (ScenePicker& p : pickers_) p.reset();
  continuity_.reset();
  nav_.unframe();
  followed_revision_ = UINT64_MAX;
  // --compare applies to the first document; later ones keep the layout the user chose.
  rebuild_views(std::exchange(options_.compare, false) || views_.compare());
  if (std::exchange(options_.difference, false)) views_.difference = true;
}

void Editor::rebuild_views(bool compare) {
  views_.rebuild(session_.doc(), prefs_, compare);
  for (ScenePicker& p : pickers_) p.reset();
}

void Editor::set_compare(bool on) {
  if (on == views_.compare() || (on && !session_.doc().scene().network)) return;
  rebuild_views(on);
  frame_shown();  // a new aspect: each panel filled again
}

void Editor::follow_document() {
  if (session_.serial() != session_serial_) after_document_replaced();
  if (views_.poll()) {
    // The worker's evaluation is uploaded: the first frame of the scene follows.
    if (!loaded_ms_) loaded_ms_ = ms_since_launch();
    if (!views_.compare_error().empty()) status_.say("cannot compare: " + views_.compare_error());
    nav_.unframe();
    for (ScenePicker& p : pickers_) p.reset();
  }
  const Document& doc = session_.doc();
  try {
    if (views_.follow(doc, prefs_.display)) status_.eval_ms = views_.last_eval_ms();
    // Each face's density from its size on screen, within the views' triangle budgets.
    const ViewRect rect = layout().panels(views_.panels())[0];
    views_.fit_to_screen(
        [&](const Vec3& c, double r) { return 2 * r / world_per_pixel(nav_.camera(), rect, c); },
        doc);
    views_.show_net(net_focus(), kPointSize * ui_scale_, doc);
  } catch (const DataError& e) {
    status_.say(e.what());
  }
  follow_figures();
  if (doc.revision() != followed_revision_) {
    followed_revision_ = doc.revision();
    follow_structure();  // an undo or a topology edit may have removed or renumbered objects
  }
  // Continuity figures follow the fine surfaces only: analysing every drag step would cost
  // more than the drag itself.
  follow_continuity(continuity_, views_, doc);
  curve_marks_.follow(doc.scene().curves);
}

uint64_t Editor::doc_revision() const {
  return session_.doc().revision();
}

void Editor::follow_figures() {
  figures_.poll();
  if (!views_.ready() || views_.panels() <= 1) return;
  const Document& doc = session_.doc();
  // Off the hot path: nothing while a drag runs (its cores are the drag's), the figures of the
  // state shown once every pane has settled.
  if (doc.dragging()) {
    figures_.cancel();
    return;
  }
  for (int i = 0; i < views_.panels(); ++i)
    if (!views_.panel(i).settled()) return;
  FiguresKey key;
  key.revision = doc.revision();
  key.faces = figures_faces(*doc.scene().network, selection_.of_kind(SelectionItem::Kind::Face));
  for (FaceScheme s : views_.setup().schemes)
    if (std::find(key.schemes.begin(), key.schemes.end(), s) == key.schemes.end())
      key.schemes.push_back(s);
  key.base = views_.setup().base;
  key.density = prefs_.fine_density;
  if (!key.faces.empty()) figures_.request(doc.scene(), key);
}

NetFocus Editor::net_focus() const {
  using Kind = SelectionItem::Kind;
  std::vector<PointRef> points = selection_.points();
  std::vector<int> edges = selection_.of_kind(Kind::Edge), faces = selection_.of_kind(Kind::Face),
                   patches = selection_.of_kind(Kind::Patch);
  const Document& doc = session_.doc();
  if (doc.dragging())
    points.insert(points.end(), doc.drag_points().begin(), doc.drag_points().end());
  // Under the cursor: the point or edge, and the surface the ray meets (not the item a click
  // would select, which a derived point shown for that surface would take away again).
  if (const auto& item = mouse_.under.item) {
    if (item->kind == Kind::Point) points.push_back(item->point);
    if (item->kind == Kind::Edge) edges.push_back(item->index);
  }
  if (mouse_.under.surface && views_.ready() && mouse_.panel >= 0) {
    const auto& surfaces = views_.panel(mouse_.panel).shown().surfaces().surfaces;
    const int s = mouse_.under.surface->surface;
    if (s >= 0 && s < int(surfaces.size())) {
      if (surfaces[s].face >= 0) faces.push_back(surfaces[s].face);
      if (surfaces[s].patch >= 0) patches.push_back(surfaces[s].patch);
    }
  }
  return pl::net_focus(points, edges, faces, patches);
}

void Editor::update_title() {
  const std::string title = session_.title() + " - PatchLab";
  if (title != shown_title_) {
    window_.set_title(title);
    shown_title_ = title;
  }
}

int Editor::run() {
  while (!quit_) {
    if (glfwWindowShouldClose(window_.handle())) {
      glfwSetWindowShouldClose(window_.handle(), GLFW_FALSE);
      dialogs_.confirm_discard("quit", [this] { quit_ = true; });
    }
    // Sleep until input unless something is animating (a drag settling, the first frames, which
    // ImGui needs to lay its windows out, or a gesture).
    const bool busy = frames_ < 4 || release_time_ || session_.doc().dragging() ||
                      mouse_.tool_has_it || nav_.gesture() != ViewNavigator::Gesture::None;
    if (views_.loading())
      glfwWaitEventsTimeout(
          kLoadingFrameSeconds);  // repaint the progress, leave the worker the cores
    else if (busy)
      glfwPollEvents();
    else
      glfwWaitEventsTimeout(kIdleWaitSeconds);
    frame();
  }
  return 0;
}

void Editor::draw_interface(const ColorRange& range) {
  draw_menu_bar(actions_);
  const EditorLayout l = layout();
  ToolContext tools = tool_context();
  SidePanel panel{prefs_,      views_, session_.doc(), selection_, actions_, continuity_,
                  work_plane_, tools_, range,          ui_scale_,  &tools,   &curve_marks_,
                  {}};
  if (debugging())
    panel.item_probe = [this](const std::string& label, float x0, float y0, float x1, float y1) {
      report_panel_item(label, x0, y0, x1, y1);
    };
  if (draw_side_panel(panel, l.menu_height, l.status_height)) rebuild_views(views_.compare());

  StatusFigures figures;
  figures.coarse = views_.ready() && !views_.settled();
  figures.selected = selection_.size();
  figures.tool = tools_.active().name();
  if (views_.ready()) figures.drawing = views_.panel(0).drawing_note();
  if (mouse_.under.item) figures.under = describe(*mouse_.under.item);
  if (work_plane_.shown && mouse_.panel >= 0) {
    const ImGuiIO& io = ImGui::GetIO();
    const Ray ray = window_ray(nav_.camera(), l.panels(views_.panels())[mouse_.panel],
                               Vec2(io.MousePos.x, io.MousePos.y));
    if (const auto p = work_plane_.hit(nav_.camera(), ray)) {
      char b[128];
      std::snprintf(b, sizeof b, "%s plane %.4g %.4g %.4g", work_plane_name(work_plane_.kind), p->x,
                    p->y, p->z);
      figures.plane = b;
    }
  }
  draw_status_bar(status_, figures, ui_scale_);

  if (views_.ready())
    draw_legend_column(
        l.legend_column(),
        view_legends(prefs_.display, views_.compare(), views_.difference, range,
                     views_.difference_range(), scheme_short_title(views_.setup().base)),
        ui_scale_);
  if (views_.ready() && views_.panels() > 1)
    draw_figures_table(l.table_strip(), figures_,
                       figures_.busy() || figures_.result_key().revision != doc_revision());
  if (prefs_.show_probe && mouse_.probe && views_.ready()) {
    const auto& meshes = views_.panel(mouse_.panel).shown().draw().surfaces;
    const int s = mouse_.probe->surface;
    std::optional<double> distance;
    if (const DifferenceField* field = views_.difference_field(mouse_.panel))
      distance = field->distance_at(*mouse_.probe);
    draw_probe_window(*mouse_.probe, s >= 0 && s < int(meshes.size()) ? meshes[s].name : "",
                      distance, ui_scale_);
  }
  if (show_help_) draw_help_window(&show_help_, actions_, help_key_, renderer_, ui_scale_);
  if (show_curvature_graph_)
    draw_curvature_graph_window(&show_curvature_graph_, session_.doc().scene(),
                                selected_curve(session_.doc().scene(), selection_), ui_scale_);
  draw_rename();
  if (context_) {
    MenuItemProbe probe;
    // Reported once, on the third frame of the menu: ImGui lays a popup out while it is hidden
    // on its first frame and may move it on the second.
    if (debugging() && ++debug_.menu_frames == 3)
      probe = [this](const std::string& label, float x0, float y0, float x1, float y1) {
        report_menu_item(label, x0, y0, x1, y1);
      };
    if (!draw_context_menu(actions_, *context_, probe)) context_.reset();
  }
  dialogs_.draw(prefs_, ui_scale_, views_.compare(), session_.doc().path().stem().string());
}

void Editor::frame() {
  const auto start = Clock::now();
  ui_scale_ = window_.follow_ui_scale(prefs_.ui_scale);  // the monitor's scale, followed
  window_.begin_frame();
  // A document replaced last frame (a menu, a dialog) first resets the parts that held the old
  // one; so does one replaced by a dropped file or a key now (handle_keys sees to that).
  if (session_.serial() != session_serial_) after_document_replaced();
  handle_drops();
  if (session_.serial() != session_serial_) after_document_replaced();
  handle_keys();
  handle_mouse();
  follow_document();
  if (views_.ready() && !nav_.framed()) open_view();
  const EditorLayout l = layout();
  nav_.follow_panel(l.display, views_.panels(), l.panels(views_.panels())[0].width);
  ViewportFrame f;
  f.window = window_.handle();
  f.renderer = &renderer_;
  f.views = &views_;
  f.doc = &session_.doc();
  f.camera = &nav_.camera();
  f.prefs = &prefs_;
  f.selection = &selection_;
  f.work_plane = &work_plane_;
  f.continuity = &continuity_;
  f.curve_marks = &curve_marks_;
  f.viewport = l.viewport();
  f.panels = l.panels(views_.panels());
  f.hover_panel = mouse_.panel;
  f.hover = &mouse_.under;
  f.probe = &mouse_.probe;
  f.ui_scale = ui_scale_;
  f.title = session_.title();
  const ColorRange range = views_.colour_range(prefs_.display, session_.doc().revision());
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
  if (release_time_ && views_.settled()) {
    status_.settle_ms = std::chrono::duration<double, std::milli>(now - *release_time_).count();
    release_time_.reset();
  }
  // The work of a frame, not the idle wait for input before it.
  status_.add_frame(std::chrono::duration<double, std::milli>(now - start).count());
  ++frames_;
  ready_frames_ = views_.ready() ? ready_frames_ + 1 : 0;
  // Report only once the layout is final (ImGui hides new windows on their first frame).
  if (ready_frames_ >= 3) report_debug_items();
  // A scene that cannot be shown is shot with its message.
  const bool failed = !views_.ready() && !views_.loading() && frames_ >= 3;
  if (options_.screenshot && (ready_frames_ == 3 || failed)) {
    take_screenshot(*options_.screenshot);
    quit_ = true;
  }
}

}  // namespace pl
