#include "app/editor/logic/editor_model.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "app/editor/logic/add_edge_tool.hpp"
#include "app/editor/logic/add_vertex_tool.hpp"
#include "app/editor/logic/comb_tips.hpp"
#include "app/editor/logic/compare_layout.hpp"
#include "app/editor/logic/launch_time.hpp"
#include "app/editor/logic/make_face_tool.hpp"
#include "app/editor/logic/new_curve_tool.hpp"
#include "app/editor/logic/select_tool.hpp"
#include "app/editor/logic/split_edge_tool.hpp"
#include "core/base/data_error.hpp"
#include "core/scene/network_edit.hpp"
#include "render/default_view.hpp"

namespace pl {

EditorModel::EditorModel(EditorModelOptions options, DocumentSession session, Preferences prefs,
                         EditorShell& shell, ViewCopyFactory copies)
    : options_(std::move(options)),
      shell_(shell),
      prefs_(std::move(prefs)),
      session_(std::move(session)),
      views_(std::move(copies)),
      autosave_(options_.autosave_dir) {
  tools_.add(std::make_unique<SelectTool>());
  tools_.add(std::make_unique<AddVertexTool>());
  tools_.add(std::make_unique<AddEdgeTool>());
  tools_.add(std::make_unique<MakeFaceTool>());
  tools_.add(std::make_unique<SplitEdgeTool>());
  tools_.add(std::make_unique<NewCurveTool>());
  register_actions();
  // A key given to two commands is a programmer's error: refuse to start (every test that
  // makes a model catches it).
  if (const auto clashes = actions_.conflicts(); !clashes.empty())
    throw std::logic_error("a key is bound to two commands: " + clashes.front());
}

EditorModel::~EditorModel() {
  autosave_.discard();  // a normal end (a crash never gets here)
}

EditorLayout EditorModel::layout() const {
  const WindowMetrics& m = metrics_;
  EditorLayout l{m.display, m.frame_height, m.frame_height + 6.0 * m.ui_scale, m.ui_scale};
  // The legends' column takes its width from the view, so no legend covers a panel.
  l.legends = int(legends({-1, 1}).size());
  // The comparison's figures under its panes: a row per face and scheme, a header and a title.
  if (views_.panels() > 1) {
    const auto& result = figures_.result();
    int rows = 0;
    if (result)
      for (const FaceFigures& f : result->faces) rows += int(f.schemes.size());
    l.table_height = (std::max(rows, 1) + 2) * m.line_height + 16 * m.ui_scale;
  }
  return l;
}

bool EditorModel::shows_surfaces() const {
  if (!views_.ready()) return false;
  for (int i = 0; i < views_.panels(); ++i)
    for (const SurfaceMesh& m : views_.panel(i).shown().draw().surfaces)
      if (!m.triangles.empty()) return true;
  return false;
}

std::vector<LegendSpec> EditorModel::legends(const ColorRange& curvature) const {
  return view_legends(prefs_.display, views_.compare(), views_.difference, shows_surfaces(),
                      curvature, views_.difference_range(),
                      scheme_short_title(views_.setup().base));
}

std::vector<Vec3> EditorModel::framing_points() const {
  const std::vector<const DrawScene*> scenes = shown_scenes();
  std::vector<Vec3> points = pl::framing_points(scenes);
  std::vector<ViewCombs> combs;
  for (int i = 0; i < int(scenes.size()); ++i) {
    const LiveCurves& curves = views_.panel(i).curves();
    ViewCombs v;
    for (auto refs : {curves.network_comb_refs(), curves.border_refs(), curves.free_comb_refs()})
      v.combs.insert(v.combs.end(), refs.begin(), refs.end());
    const Box box = scenes[i]->bounds();
    v.diagonal = box.empty() ? 0.0 : glm::length(box.hi - box.lo);
    combs.push_back(std::move(v));
  }
  const std::vector<Vec3> tips = comb_tips(combs, prefs_.display);
  points.insert(points.end(), tips.begin(), tips.end());
  return points;
}

Box EditorModel::scene_box() const {
  return views_.ready() ? views_.panel(0).shown().draw().bounds() : Box();
}

PickScene EditorModel::pick_scene(int panel, std::vector<SelectionItem>& items) const {
  const LiveSurfaces& live = views_.panel(panel).shown();
  items = surface_items(live.surfaces());
  return {live.draw().surfaces, items, live.draw().network_curves, &live.points(),
          live.draw().free_curves};
}

ToolContext EditorModel::tool_context() {
  return {session_.doc(),
          selection_,
          nav_.camera(),
          work_plane_,
          [this](const std::string& m) { say(m); },
          metrics_.ui_scale};
}

void EditorModel::follow_session() {
  if (session_.serial() != session_serial_) after_document_replaced();
}

void EditorModel::after_document_replaced() {
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
  status_.clear_figures();
  followed_revision_ = UINT64_MAX;
  // The comparison asked for at start applies to the first document; later ones keep the
  // layout the user chose.
  rebuild_views(std::exchange(options_.compare, false) || views_.compare());
  if (std::exchange(options_.difference, false)) views_.difference = true;
  // A small scene is evaluated within rebuild(): its time is the new document's figure.
  if (views_.ready()) status_.eval_ms = views_.last_eval_ms();
}

void EditorModel::rebuild_views(bool compare) {
  views_.rebuild(session_.doc(), prefs_, compare);
  for (ScenePicker& p : pickers_) p.reset();
}

void EditorModel::set_compare(bool on) {
  if (on == views_.compare() || (on && !session_.doc().scene().network)) return;
  rebuild_views(on);
  frame_shown();  // a new aspect: each panel filled again
}

void EditorModel::update() {
  follow_session();
  if (views_.poll()) {
    // The worker's evaluation is taken: the first frame of the scene follows.
    if (!loaded_ms_) loaded_ms_ = ms_since_launch();
    status_.eval_ms = views_.last_eval_ms();
    if (!views_.compare_error().empty()) say("cannot compare: " + views_.compare_error());
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
    views_.show_net(net_focus(), metrics_.point_px, doc);
  } catch (const DataError& e) {
    say(e.what());
  }
  follow_figures();
  if (doc.revision() != followed_revision_) {
    followed_revision_ = doc.revision();
    follow_structure();  // an undo or a topology edit may have removed or renumbered objects
  }
  // Continuity figures follow the fine surfaces only: analysing every drag step would cost
  // more than the drag itself.
  follow_continuity();
  curve_marks_.follow(doc.scene().curves);
  if (views_.ready() && !nav_.framed()) open_view();
  const EditorLayout l = layout();
  nav_.follow_panel(l.display, views_.panels(), l.panels(views_.panels())[0].width);
}

void EditorModel::follow_figures() {
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

void EditorModel::follow_structure() {
  const Selection::Followed f = selection_.follow(session_.doc().scene());
  // What was picked under the mouse came from the network as it was.
  if (selection_.structure_serial() != mouse_.structure) {
    mouse_.structure = selection_.structure_serial();
    mouse_.under = {};
    mouse_.pressed = {};
  }
  // Indices may name other objects now: the tool's picks go too.
  if (f == Selection::Followed::Cleared) {
    ToolContext ctx = tool_context();
    tools_.active().cancel(ctx);
  }
}

void EditorModel::follow_continuity() {
  if (!views_.ready()) return;
  // The figures follow the fine surfaces only, once they have settled.
  std::vector<ContinuityMonitor::Input> inputs;
  if (views_.panels() > 1) {
    for (int i = 0; i < views_.panels(); ++i) {
      if (!views_.panel(i).settled()) return;
      inputs.push_back({scheme_title(views_.setup().schemes[i]) + " filling",
                        &views_.panel(i).fine().surfaces()});
    }
  } else {
    if (!views_.settled()) return;
    inputs.push_back({"", &views_.main()->fine().surfaces()});
  }
  continuity_.follow(session_.doc().scene(), inputs, session_.doc().revision());
}

NetFocus EditorModel::net_focus() const {
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

std::vector<const DrawScene*> EditorModel::shown_scenes() const {
  std::vector<const DrawScene*> scenes;
  if (views_.ready())
    for (int i = 0; i < views_.panels(); ++i) scenes.push_back(&views_.panel(i).shown().draw());
  return scenes;
}

void EditorModel::open_view() {
  nav_.open_view(shown_scenes(), layout().panels(views_.panels())[0].aspect());
}

void EditorModel::frame_shown() {
  nav_.frame_tightly(shown_scenes(), layout().panels(views_.panels())[0].aspect());
}

bool EditorModel::moving() const {
  return session_.doc().dragging() || mouse_.tool_has_it ||
         nav_.gesture() != ViewNavigator::Gesture::None;
}

}  // namespace pl
