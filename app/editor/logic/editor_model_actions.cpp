// The editor's action table: every command with its menu place, keys and help, bound to the
// parts that carry it out, a group per menu. The menu bar, the context menu, the keys and F1 are
// drawn from it; an authoring command is one more entry here (or in a GUI-free add_*_actions
// function). What needs a window (a dialog, the help) is asked of the shell.
#include <algorithm>

#include "app/editor/logic/add_vertex_tool.hpp"
#include "app/editor/logic/authoring_actions.hpp"
#include "app/editor/logic/curve_actions.hpp"
#include "app/editor/logic/editor_model.hpp"
#include "app/editor/logic/interior_actions.hpp"
#include "app/editor/logic/make_face_tool.hpp"
#include "app/editor/logic/patch_actions.hpp"
#include "app/editor/logic/selection_actions.hpp"
#include "app/editor/logic/selection_properties.hpp"

namespace pl {

namespace {

constexpr ContextSet kOnObjects =
    context_bit(ContextTarget::Point) | context_bit(ContextTarget::Edge) |
    context_bit(ContextTarget::Face) | context_bit(ContextTarget::Patch) |
    context_bit(ContextTarget::Curve);

}  // namespace

void EditorModel::register_actions() {
  add_file_actions();
  add_edit_actions();
  add_object_actions();
  add_view_actions();
  add_work_plane_actions();
  add_tool_actions();
}

void EditorModel::add_file_actions() {
  ActionRegistry& r = actions_;
  r.add(make_action("file.new", "File", "New", {"Ctrl+N"}, "new empty scene", [this] {
    shell_.confirm_discard("start a new scene", [this] { new_scene(); });
  }));
  r.add(make_action(
      "file.open", "File", "Open...", {"Ctrl+O"},
      "open a scene (.json), a GB patch (.gbp), or curves (.obj polylines, .step/.igs edges)",
      [this] { shell_.confirm_discard("open another file", [this] { shell_.ask_open(); }); }));
  r.add(make_action("file.save", "File", "Save", {"Ctrl+S"}, "save (asks for a name when untitled)",
                    [this] { save(); }));
  r.add(make_action("file.save_as", "File", "Save As...", {"Ctrl+Shift+S"}, "save under a new name",
                    [this] { shell_.ask_save_as(); }));
  Action exporting = make_action(
      "file.export", "File", "Export...", {},
      "the fine surfaces as a mesh (OBJ, PLY, OFF, STL), or the patches as CAD surfaces "
      "(STEP .step/.stp, IGES .igs/.iges)",
      [this] {
        export_format_ = nullptr;  // the typed extension decides
        shell_.ask_export();
      });
  exporting.separator_before = true;
  exporting.enabled = [this] { return views_.ready(); };
  const auto not_shown = [this] {
    return std::string(views_.loading() ? "the scene is still being evaluated"
                                        : "the scene could not be evaluated");
  };
  exporting.why_disabled = not_shown;
  r.add(std::move(exporting));
  // The same with the format chosen first: it decides, and a name typed without an extension
  // gets the format's.
  for (const ExportFormat& f : export_formats()) {
    Action as = make_action("file.export." + f.id, "File/Export As", f.label + "...", {},
                            f.cad ? "the patches as CAD surfaces, " + f.extensions.front()
                                  : "the fine surfaces as a mesh, " + f.extensions.front(),
                            [this, format = &f] {
                              export_format_ = format;
                              shell_.ask_export();
                            });
    as.enabled = [this] { return views_.ready(); };
    as.why_disabled = not_shown;
    r.add(std::move(as));
  }
  r.add(make_action("file.screenshot", "File", "Screenshot...", {}, "render the view to a PNG",
                    [this] { shell_.ask_screenshot(); }));
  Action quit = make_action("file.quit", "File", "Quit", {"Ctrl+Q"}, "quit", [this] {
    shell_.confirm_discard("quit", [this] { quit_requested = true; });
  });
  quit.separator_before = true;
  r.add(std::move(quit));
}

void EditorModel::add_edit_actions() {
  ActionRegistry& r = actions_;
  Action undo = make_action("edit.undo", "Edit", "Undo", {"Ctrl+Z"}, "undo", [this] {
    ToolContext ctx = tool_context();
    const bool held = mouse_.tool_has_it;
    tools_.active().cancel(ctx);
    mouse_.tool_has_it = false;
    // During a drag, undo takes back the drag only.
    if (held || session_.doc().dragging())
      session_.doc().cancel_drag();
    else
      session_.doc().undo();
  });
  undo.detail = [this] { return session_.doc().undo_label(); };
  undo.enabled = [this] { return session_.doc().can_undo() || session_.doc().dragging(); };
  undo.why_disabled = [] { return std::string("nothing to undo"); };
  r.add(std::move(undo));
  Action redo =
      make_action("edit.redo", "Edit", "Redo", {"Ctrl+Shift+Z", "Ctrl+Y"}, "redo", [this] {
        ToolContext ctx = tool_context();
        tools_.active().cancel(ctx);
        mouse_.tool_has_it = false;
        session_.doc().redo();
      });
  redo.detail = [this] { return session_.doc().redo_label(); };
  redo.enabled = [this] { return session_.doc().can_redo(); };
  redo.why_disabled = [] { return std::string("nothing to redo"); };
  r.add(std::move(redo));
  Action esc = make_action("edit.escape", "Edit", "Cancel / Clear Selection", {"Esc"},
                           "cancel a drag, else back to the Select tool, else clear the selection",
                           [this] { escape(); });
  esc.separator_before = true;
  r.add(std::move(esc));
  // One action for every arrow: the key that triggered it says which way and how far.
  std::vector<std::string> arrows;
  for (const char* mod : {"", "Shift+", "Alt+"})
    for (const char* key : {"Left", "Right", "Up", "Down", "PgUp", "PgDn"})
      arrows.push_back(std::string(mod) + key);
  Action nudge = make_action(
      "edit.nudge", "", "Nudge", arrows,
      "nudge the selected points in the view plane / along the view (Shift x10, Alt x0.1)",
      nullptr);
  nudge.run = [this](const std::optional<KeyChord>& k) {
    if (k) nudge_selection(*k);
  };
  nudge.keys_text = "Arrows, PgUp/PgDn";
  nudge.enabled = [this] { return !selection_.points().empty(); };
  nudge.why_disabled = [] { return std::string("select points to nudge"); };
  r.add(std::move(nudge));
}

// Select, Face, Network and Curve: the GUI-free groups shared with the tests, and what acts where
// the context menu was opened.
void EditorModel::add_object_actions() {
  ActionRegistry& r = actions_;
  const Say say = [this](const std::string& m) { status_.say(m); };
  add_selection_actions(r, session_.doc(), selection_, say);
  AuthoringHooks hooks;
  hooks.say = say;
  hooks.towards = [this] { return towards_viewer(nav_.camera()); };
  // "Split Edge" from the right-click menu on an edge splits it where it was clicked.
  hooks.split_parameter = [this](int e) -> std::optional<double> {
    if (context_ == ContextTarget::Edge && mouse_.pressed.edge == e) return mouse_.pressed.edge_t;
    return std::nullopt;
  };
  Action vertex_here = make_action(
      "network.add_vertex_here", "Network", "Add Vertex Here", {},
      "from the right-click menu: a vertex where it was opened, on the surface there or else on "
      "the work plane (the Add Vertex tool, V, adds one per click)",
      [this] {
        ToolContext ctx = tool_context();
        AddVertexTool().add_at(ctx, *mouse_.pressed_placement);
      });
  vertex_here.context = context_bit(ContextTarget::Empty) | context_bit(ContextTarget::Face);
  vertex_here.enabled = [this] {
    return (context_ == ContextTarget::Empty || context_ == ContextTarget::Face) &&
           mouse_.pressed_placement.has_value();
  };
  r.add(std::move(vertex_here));
  add_authoring_actions(r, session_.doc(), selection_, hooks);
  add_patch_actions(r, session_.doc(), selection_, say);
  add_interior_actions(r, session_.doc(), selection_, say);
  CurveActionHooks curve_hooks;
  curve_hooks.say = say;
  // A right-click menu acts where it was opened: on a point there, else on the work plane.
  curve_hooks.menu_point = [this]() -> std::optional<Vec3> {
    if (!context_) return std::nullopt;
    return mouse_.pressed_point ? mouse_.pressed_point : mouse_.pressed_placement;
  };
  add_curve_actions(r, session_.doc(), selection_, curve_hooks);
  Action graph = make_action("curve.curvature_graph", "Curve", "Curvature Graph", {},
                             "curvature against t of the selected curve, in a window",
                             [this] { show_curvature_graph = !show_curvature_graph; });
  graph.separator_before = true;
  graph.checked = [this] { return show_curvature_graph; };
  graph.context = context_bit(ContextTarget::Point) | context_bit(ContextTarget::Curve) |
                  context_bit(ContextTarget::Empty);
  graph.enabled = [this] { return selected_curve(session_.doc().scene(), selection_).has_value(); };
  graph.why_disabled = [] { return std::string("select a free curve or one of its points"); };
  r.add(std::move(graph));
  Action rename = make_action("edit.rename", "Edit", "Rename...", {"F2"},
                              "name the selected face or edge", [this] { start_rename(); });
  rename.context = context_bit(ContextTarget::Face) | context_bit(ContextTarget::Edge);
  rename.enabled = [this] {
    return selection_.size() == 1 &&
           (selection_.has(SelectionItem::Kind::Face) || selection_.has(SelectionItem::Kind::Edge));
  };
  rename.why_disabled = [] { return std::string("select one face or one edge to rename"); };
  r.add(std::move(rename));
}

void EditorModel::add_view_actions() {
  ActionRegistry& r = actions_;
  auto aspect = [this] { return layout().panels(views_.panels())[0].aspect(); };
  Action all =
      make_action("view.frame_all", "View", "Frame All", {"F"},
                  "frame everything drawn (with the curvature combs when shown), with a margin",
                  [this, aspect] { nav_.frame_all(framing_points(), aspect()); });
  all.context = context_bit(ContextTarget::Empty);
  r.add(std::move(all));
  Action sel =
      make_action("view.frame_selection", "View", "Frame Selection", {"Shift+F"},
                  "frame the selection", [this, aspect] {
                    const Box b = selection_bounds(session_.doc().scene(), selection_);
                    b.empty() ? nav_.frame(scene_box(), aspect()) : nav_.frame_closely(b, aspect());
                  });
  sel.enabled = [this] { return !selection_.empty(); };
  sel.why_disabled = [] { return std::string("nothing selected"); };
  sel.context = kOnObjects;
  r.add(std::move(sel));
  const std::pair<const char*, ViewPreset> presets[] = {{"Front", ViewPreset::Front},
                                                        {"Right", ViewPreset::Right},
                                                        {"Top", ViewPreset::Top},
                                                        {"Iso", ViewPreset::Iso}};
  const char* preset_keys[] = {"1", "3", "7", "0"};
  for (int i = 0; i < 4; ++i) {
    const ViewPreset p = presets[i].second;
    std::string id = std::string("view.") + presets[i].first;
    std::transform(id.begin(), id.end(), id.begin(), ::tolower);
    Action a = make_action(id, "View", presets[i].first, {preset_keys[i]},
                           std::string(presets[i].first) + " view",
                           [this, p, aspect] { nav_.preset(p, scene_box(), aspect()); });
    a.separator_before = i == 0;
    r.add(std::move(a));
  }
  Action ortho =
      make_action("view.orthographic", "View", "Orthographic", {"5"}, "orthographic on/off",
                  [this] { nav_.camera().orthographic = !nav_.camera().orthographic; });
  ortho.checked = [this] { return nav_.camera().orthographic; };
  r.add(std::move(ortho));
  Action compare =
      make_action("view.compare", "View", "Compare Schemes", {"C"},
                  "the network filled by each chosen scheme side by side (Display panel)",
                  [this] { set_compare(!views_.compare()); });
  compare.separator_before = true;
  compare.checked = [this] { return views_.compare(); };
  compare.enabled = [this] { return session_.doc().scene().network.has_value(); };
  compare.why_disabled = [] { return std::string("the scene has no network to fill by schemes"); };
  r.add(std::move(compare));
  Action difference = make_action("view.difference", "View", "Difference Colouring", {"D"},
                                  "colour every pane by its distance to the base pane (comparison)",
                                  [this] { views_.difference = !views_.difference; });
  difference.checked = [this] { return views_.difference; };
  difference.enabled = [this] { return views_.compare(); };
  difference.why_disabled = [] { return std::string("only in the comparison (C)"); };
  r.add(std::move(difference));
  Action probe = make_action("view.probe", "View", "Probe Under Cursor", {}, "",
                             [this] { prefs_.show_probe = !prefs_.show_probe; });
  probe.checked = [this] { return prefs_.show_probe; };
  r.add(std::move(probe));
}

void EditorModel::add_work_plane_actions() {
  ActionRegistry& r = actions_;
  Action grid =
      make_action("plane.grid", "View/Work Plane", "Show Grid", {"G"}, "work-plane grid on/off",
                  [this] { work_plane_.shown = !work_plane_.shown; });
  grid.checked = [this] { return work_plane_.shown; };
  grid.context = context_bit(ContextTarget::Empty);
  r.add(std::move(grid));
  Action snap = make_action(
      "plane.snap", "View/Work Plane", "Snap", {"Shift+G"},
      "new points snap to vertices, curve points, ends, midpoints and curves near the cursor, "
      "else to the grid (hold Alt to place freely)",
      [this] {
        work_plane_.snap = !work_plane_.snap;
        say(work_plane_.snap ? "snapping on (Alt places freely)" : "snapping off");
      });
  snap.checked = [this] { return work_plane_.snap; };
  snap.context = context_bit(ContextTarget::Empty);
  r.add(std::move(snap));
  for (WorkPlaneKind k :
       {WorkPlaneKind::View, WorkPlaneKind::XY, WorkPlaneKind::XZ, WorkPlaneKind::YZ}) {
    std::string id = std::string("plane.") + work_plane_name(k);
    std::transform(id.begin(), id.end(), id.begin(), ::tolower);
    Action a = make_action(id, "View/Work Plane", std::string(work_plane_name(k)) + " Plane", {},
                           "", [this, k] {
                             work_plane_.kind = k;
                             work_plane_.shown = true;
                           });
    a.separator_before = k == WorkPlaneKind::View;
    a.checked = [this, k] { return work_plane_.kind == k; };
    r.add(std::move(a));
  }
  Action here = make_action("plane.at_cursor", "View/Work Plane", "Through the Point Clicked", {},
                            "the work plane through the point right-clicked", [this] {
                              if (mouse_.pressed_point) work_plane_.origin = *mouse_.pressed_point;
                              work_plane_.shown = true;
                            });
  here.separator_before = true;
  here.enabled = [this] { return mouse_.pressed_point.has_value(); };
  here.context = kOnObjects;
  r.add(std::move(here));
  Action at_sel = make_action("plane.at_selection", "View/Work Plane", "Through the Selection", {},
                              "the work plane through the centre of the selection", [this] {
                                const Box b = selection_bounds(session_.doc().scene(), selection_);
                                if (!b.empty()) work_plane_.origin = b.centre();
                                work_plane_.shown = true;
                              });
  at_sel.enabled = [this] { return !selection_.empty(); };
  r.add(std::move(at_sel));
  r.add(make_action("plane.at_origin", "View/Work Plane", "Through the Origin", {}, "",
                    [this] { work_plane_.origin = Vec3(0); }));
}

// One entry per tool of the tool box, checked while active; Finish; the help.
void EditorModel::add_tool_actions() {
  ActionRegistry& r = actions_;
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    const Tool& tool = tools_.tool(i);
    std::string id = "tool." + tool.name();
    std::transform(id.begin(), id.end(), id.begin(), ::tolower);
    std::vector<std::string> keys;
    if (!tool.shortcut().empty()) keys.push_back(tool.shortcut());
    Action a = make_action(id, "Tools", tool.name(), keys, tool.hint(), [this, i] {
      ToolContext ctx = tool_context();
      tools_.activate(i, ctx);
      if (tools_.active().places_on_work_plane()) work_plane_.shown = true;
    });
    a.checked = [this, i] { return tools_.active_index() == i; };
    r.add(std::move(a));
  }

  Action finish = make_action("tool.finish", "Tools", "Finish", {"Enter"},
                              "complete what the tool has picked (Make Face: the face)", [this] {
                                ToolContext ctx = tool_context();
                                tools_.active().finish(ctx);
                              });
  finish.separator_before = true;
  finish.enabled = [this] {
    ToolContext ctx = tool_context();
    return tools_.active().can_finish(ctx);
  };
  r.add(std::move(finish));

  // Help
  Action help = make_action("help.keys", "Help", "Mouse and Keys", {"F1"}, "this list",
                            [this] { show_help = !show_help; });
  help.checked = [this] { return show_help; };
  r.add(std::move(help));
}

}  // namespace pl
