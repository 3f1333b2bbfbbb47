// The editor's action table: every command with its menu place, keys and help, bound to the
// parts that carry it out. The menu bar, the context menu, the keys and F1 are drawn from it;
// an authoring command is one more entry here (or in a GUI-free add_*_actions function).
#include <algorithm>

#include "app/editor/editor.hpp"
#include "app/editor/logic/selection_actions.hpp"
#include "app/editor/logic/selection_properties.hpp"

namespace pl {

namespace {

using Run = std::function<void(const std::optional<KeyChord>&)>;

Action make(std::string id, std::string menu, std::string label, std::vector<std::string> keys,
            std::string help, Run run) {
  Action a;
  a.id = std::move(id);
  a.menu = std::move(menu);
  a.label = std::move(label);
  for (const std::string& k : keys) a.keys.push_back(*parse_chord(k));
  a.help = std::move(help);
  a.run = std::move(run);
  return a;
}

// Runs `f` ignoring the key that triggered it.
template <class F>
Run plain(F f) {
  return [f](const std::optional<KeyChord>&) { f(); };
}

constexpr ContextSet kOnObjects =
    context_bit(ContextTarget::Point) | context_bit(ContextTarget::Edge) |
    context_bit(ContextTarget::Face) | context_bit(ContextTarget::Patch);

}  // namespace

void Editor::register_actions() {
  ActionRegistry& r = actions_;
  auto has_selection = [this] { return !selection_.empty(); };
  auto aspect = [this] { return layout().panels(views_.compare())[0].aspect(); };

  // File
  r.add(make("file.new", "File", "New", {"Ctrl+N"}, "new empty scene", plain([this] {
               dialogs_.confirm_discard("start a new scene", [this] { new_scene(); });
             })));
  r.add(make("file.open", "File", "Open...", {"Ctrl+O"}, "open a scene (.json) or GB patch (.gbp)",
             plain([this] {
               dialogs_.confirm_discard("open another file", [this] {
                 dialogs_.browse(FileDialogs::Purpose::Open, browse_start_dir());
               });
             })));
  r.add(make("file.save", "File", "Save", {"Ctrl+S"}, "save (asks for a name when untitled)",
             plain([this] { save(); })));
  r.add(make("file.save_as", "File", "Save As...", {"Ctrl+Shift+S"}, "save under a new name",
             plain([this] {
               dialogs_.browse(FileDialogs::Purpose::SaveAs, browse_start_dir(),
                               session_.doc().path().filename().string());
             })));
  Action exporting = make("file.export", "File", "Export Mesh...", {},
                          "the fine surfaces as OBJ, PLY, OFF or STL", plain([this] {
                            dialogs_.browse(FileDialogs::Purpose::ExportMesh, browse_start_dir(),
                                            session_.doc().path().stem().string() + ".obj");
                          }));
  exporting.separator_before = true;
  exporting.enabled = [this] { return views_.ready(); };
  r.add(std::move(exporting));
  r.add(make("file.screenshot", "File", "Screenshot...", {}, "render the view to a PNG",
             plain([this] { dialogs_.show_screenshot_options(); })));
  Action quit = make("file.quit", "File", "Quit", {"Ctrl+Q"}, "quit",
                     plain([this] { dialogs_.confirm_discard("quit", [this] { quit_ = true; }); }));
  quit.separator_before = true;
  r.add(std::move(quit));

  // Edit
  Action undo = make("edit.undo", "Edit", "Undo", {"Ctrl+Z"}, "undo", plain([this] {
                       ToolContext ctx = tool_context();
                       tools_.active().cancel(ctx);
                       session_.doc().undo();
                     }));
  undo.detail = [this] { return session_.doc().undo_label(); };
  undo.enabled = [this] { return session_.doc().can_undo() || session_.doc().dragging(); };
  r.add(std::move(undo));
  Action redo = make("edit.redo", "Edit", "Redo", {"Ctrl+Shift+Z", "Ctrl+Y"}, "redo", plain([this] {
                       ToolContext ctx = tool_context();
                       tools_.active().cancel(ctx);
                       session_.doc().redo();
                     }));
  redo.detail = [this] { return session_.doc().redo_label(); };
  redo.enabled = [this] { return session_.doc().can_redo(); };
  r.add(std::move(redo));
  Action esc = make("edit.escape", "Edit", "Cancel / Clear Selection", {"Esc"},
                    "cancel a drag, else back to the Select tool, else clear the selection",
                    plain([this] { escape(); }));
  esc.separator_before = true;
  r.add(std::move(esc));
  Action nudge = make("edit.nudge", "", "Nudge", {"Left", "Right", "Up", "Down", "PgUp", "PgDn"},
                      "nudge the selected points in the view plane / along the view (Shift x10, "
                      "Alt x0.1)",
                      [this](const std::optional<KeyChord>& k) {
                        if (k) nudge_selection(*k);
                      });
  for (const char* mod : {"Shift+", "Alt+"})
    for (const char* key : {"Left", "Right", "Up", "Down", "PgUp", "PgDn"})
      nudge.keys.push_back(*parse_chord(std::string(mod) + key));
  nudge.keys_text = "Arrows, PgUp/PgDn";
  nudge.enabled = [this] { return !selection_.points().empty(); };
  r.add(std::move(nudge));

  // Select and Face (GUI-free, shared with the tests)
  add_selection_actions(r, session_.doc(), selection_);

  // View
  Action all = make("view.frame_all", "View", "Frame All", {"F"}, "frame all",
                    plain([this, aspect] { nav_.frame(scene_box(), aspect()); }));
  all.context = context_bit(ContextTarget::Empty);
  r.add(std::move(all));
  Action sel =
      make("view.frame_selection", "View", "Frame Selection", {"Shift+F"}, "frame the selection",
           plain([this, aspect] {
             const Box b = selection_bounds(session_.doc().scene(), selection_);
             b.empty() ? nav_.frame(scene_box(), aspect()) : nav_.frame_closely(b, aspect());
           }));
  sel.enabled = has_selection;
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
    Action a = make(id, "View", presets[i].first, {preset_keys[i]},
                    std::string(presets[i].first) + " view",
                    plain([this, p, aspect] { nav_.preset(p, scene_box(), aspect()); }));
    a.separator_before = i == 0;
    r.add(std::move(a));
  }
  Action ortho = make("view.orthographic", "View", "Orthographic", {"5"}, "orthographic on/off",
                      plain([this] { nav_.camera().orthographic = !nav_.camera().orthographic; }));
  ortho.checked = [this] { return nav_.camera().orthographic; };
  r.add(std::move(ortho));
  Action compare =
      make("view.compare", "View", "Compare Gregory | GB", {"C"},
           "compare Gregory | GB side by side", plain([this] { set_compare(!views_.compare()); }));
  compare.separator_before = true;
  compare.checked = [this] { return views_.compare(); };
  compare.enabled = [this] { return session_.doc().scene().network.has_value(); };
  r.add(std::move(compare));
  Action difference = make("view.difference", "View", "Difference Colouring", {"D"},
                           "colour GB by its distance to Gregory (comparison)",
                           plain([this] { views_.difference = !views_.difference; }));
  difference.checked = [this] { return views_.difference; };
  difference.enabled = [this] { return views_.compare(); };
  r.add(std::move(difference));
  Action probe = make("view.probe", "View", "Probe Under Cursor", {}, "",
                      plain([this] { prefs_.show_probe = !prefs_.show_probe; }));
  probe.checked = [this] { return prefs_.show_probe; };
  r.add(std::move(probe));

  // Work plane
  Action grid = make("plane.grid", "View/Work Plane", "Show Grid", {"G"}, "work-plane grid on/off",
                     plain([this] { work_plane_.shown = !work_plane_.shown; }));
  grid.checked = [this] { return work_plane_.shown; };
  grid.context = context_bit(ContextTarget::Empty);
  r.add(std::move(grid));
  for (WorkPlaneKind k :
       {WorkPlaneKind::View, WorkPlaneKind::XY, WorkPlaneKind::XZ, WorkPlaneKind::YZ}) {
    std::string id = std::string("plane.") + work_plane_name(k);
    std::transform(id.begin(), id.end(), id.begin(), ::tolower);
    Action a = make(id, "View/Work Plane", std::string(work_plane_name(k)) + " Plane", {}, "",
                    plain([this, k] {
                      work_plane_.kind = k;
                      work_plane_.shown = true;
                    }));
    a.separator_before = k == WorkPlaneKind::View;
    a.checked = [this, k] { return work_plane_.kind == k; };
    r.add(std::move(a));
  }
  Action here = make("plane.at_cursor", "View/Work Plane", "Through the Point Clicked", {},
                     "the work plane through the point right-clicked", plain([this] {
                       if (mouse_.pressed_point) work_plane_.origin = *mouse_.pressed_point;
                       work_plane_.shown = true;
                     }));
  here.separator_before = true;
  here.enabled = [this] { return mouse_.pressed_point.has_value(); };
  here.context = kOnObjects;
  r.add(std::move(here));
  Action at_sel = make("plane.at_selection", "View/Work Plane", "Through the Selection", {},
                       "the work plane through the centre of the selection", plain([this] {
                         const Box b = selection_bounds(session_.doc().scene(), selection_);
                         if (!b.empty()) work_plane_.origin = b.centre();
                         work_plane_.shown = true;
                       }));
  at_sel.enabled = has_selection;
  r.add(std::move(at_sel));
  r.add(make("plane.at_origin", "View/Work Plane", "Through the Origin", {}, "",
             plain([this] { work_plane_.origin = Vec3(0); })));

  // Tools: one entry per tool of the tool box, checked while active.
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    std::string id = "tool." + tools_.tool(i).name();
    std::transform(id.begin(), id.end(), id.begin(), ::tolower);
    Action a = make(id, "Tools", tools_.tool(i).name(), {}, tools_.tool(i).hint(), plain([this, i] {
                      ToolContext ctx = tool_context();
                      tools_.activate(i, ctx);
                    }));
    a.checked = [this, i] { return tools_.active_index() == i; };
    r.add(std::move(a));
  }

  // Help
  Action help = make("help.keys", "Help", "Mouse and Keys", {"F1"}, "this list",
                     plain([this] { show_help_ = !show_help_; }));
  help.checked = [this] { return show_help_; };
  r.add(std::move(help));
}

}  // namespace pl
