// What scripts and the end-to-end tests read back from a running editor (--debug-point): where
// objects are on screen, the selection after each change, the context menu's items, the saves.
// Lines on stdout:
//   debug-point X Y window WX WY world-per-pixel S right RX RY RZ up UX UY UZ   (a point)
//   debug-face NAME X Y window WX WY      (a pixel that selects the face, patch or edge NAME;
//   debug-edge NAME X Y window WX WY       NAME as "face 1", "edge 3", "patch 0";
//   debug-curve NAME X Y window WX WY      a free curve's line, NAME as "curve 0")
//   selection: ITEM, ITEM, ...            (after every change; "selection: none" when empty)
//   menu-item LABEL X Y window WX WY      (the centre of each context-menu item, once laid out)
//   panel-item LABEL X Y window WX WY rect X0 Y0 X1 Y1
//                                         (the centre and rectangle of a side-panel item, when it
//                                          appears or moves: the tool buttons and hint, the
//                                          interior buttons of a face, a "tooltip")
//   saved PATH revision N
// With --debug-state, also (window pixels relative to the window, like the lines above):
//   pointer down|up B X Y [shift] [ctrl] [alt]   (as the frame saw the press or release)
//   pointer at X Y                               (the cursor moved while a button is held)
//   status MESSAGE                               (every new status-bar message)
//   text-input 1|0                               (a text field took or gave up the keyboard)
//   help-window 1|0 [focused]                    (F1's window opened (with the keyboard focus)
//                                                 or closed)
// and, whenever it changed, the state at rest (no button held, no drag, fine surfaces shown):
//   state revision R vertices V edges E faces F curves C selected N can-undo U can-redo D tool NAME
//   view OX OY XX XY YX YY ZX ZY window WX WY    (pixels of the world origin and of the unit
//                                                 points on x, y, z: affine in orthographic)
//   vertex I X Y
//   curve-point C K X Y                          (control point K of free curve C)
//   edge I X Y | edge I hidden                   (a pixel that picks the edge's curve)
//   curve C X Y | curve C hidden                 (a pixel that picks free curve C by its line)
//   joint A B G2 gap G angle D jump J            (a joint of free curves A and B: class, figures)
//   face I X Y | face I hidden                   (a pixel that picks the face's surface)
//   free-point F NAME X Y                        (free point NAME of GB face F as drawn:
//                                                 "centre" or "S,J,K"; shown points only)
//   knob V X Y                                   (the normal knob of a selected vertex)
//   state-end R
#include <imgui.h>

#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/editor/editor.hpp"
#include "app/editor/logic/plane_handles.hpp"

namespace pl {

void Editor::report_debug_items() {
  if (!debugging() || debug_.positions || !model_.views().ready()) return;
  const auto rects = model_.layout().panels(model_.views().panels());
  const Camera& camera = model_.nav().camera();
  const auto [wx, wy] = window_.position();
  for (const SelectionItem& item : options_.debug_items) {
    if (!item_exists(model_.session().doc().scene(), item)) {
      std::cout << "debug-missing " << describe(item) << std::endl;
      continue;
    }
    if (item.kind == SelectionItem::Kind::Point) {
      const Vec3 p = point_position(model_.session().doc().scene(), item.point);
      const auto s = project_to_window(camera, rects[0], p);
      if (!s) return;  // not in view yet: try again next frame
      const double wpp = world_per_pixel(camera, rects[0], p);
      const Vec3 r = camera.right(), u = camera.up();
      std::printf(
          "debug-point %.3f %.3f window %d %d world-per-pixel %.17g right %.17g %.17g %.17g "
          "up %.17g %.17g %.17g\n",
          s->x, s->y, wx, wy, wpp, r.x, r.y, r.z, u.x, u.y, u.z);
      continue;
    }
    std::vector<SelectionItem> items;
    const DisplaySettings& d = model_.prefs().display;
    const auto px = find_pixel_for(model_.picker(0), model_.pick_scene(0, items), camera, rects[0],
                                   item, {d.control_net, d.network_curves});
    const char* kind = item.kind == SelectionItem::Kind::Edge    ? "debug-edge"
                       : item.kind == SelectionItem::Kind::Curve ? "debug-curve"
                                                                 : "debug-face";
    if (px)
      std::printf("%s %s %.3f %.3f window %d %d\n", kind, describe(item).c_str(), px->x, px->y, wx,
                  wy);
    else
      std::printf("%s %s hidden\n", kind, describe(item).c_str());
  }
  std::fflush(stdout);
  debug_.positions = true;
}

void Editor::report_selection_change() {
  if (model_.selection().serial() == debug_.selection) return;
  debug_.selection = model_.selection().serial();
  std::cout << "selection: "
            << (model_.selection().empty() ? "none" : describe(model_.selection(), 64))
            << std::endl;
}

void Editor::report_menu_item(const std::string& label, float x0, float y0, float x1, float y1) {
  const auto [wx, wy] = window_.position();
  std::printf("menu-item %s %.1f %.1f window %d %d\n", label.c_str(), 0.5 * (x0 + x1),
              0.5 * (y0 + y1), wx, wy);
  std::fflush(stdout);
}

void Editor::report_panel_item(const std::string& label, float x0, float y0, float x1, float y1) {
  const auto [wx, wy] = window_.position();
  char line[256];
  std::snprintf(line, sizeof line, "panel-item %s %.1f %.1f window %d %d rect %.1f %.1f %.1f %.1f",
                label.c_str(), 0.5 * (x0 + x1), 0.5 * (y0 + y1), wx, wy, x0, y0, x1, y1);
  std::string& last = debug_.panel_items[label];
  if (last == line) return;
  last = line;
  std::printf("%s\n", line);
  std::fflush(stdout);
}

namespace {

std::string pixel(const std::optional<Vec2>& p) {
  if (!p) return "hidden";
  char b[64];
  std::snprintf(b, sizeof b, "%.1f %.1f", p->x, p->y);
  return b;
}

}  // namespace

void Editor::report_state() {
  const ImGuiIO& io = ImGui::GetIO();
  // What the pointer did this frame, as the editor saw it.
  for (int b = 0; b < 3; ++b) {
    const char* what = ImGui::IsMouseClicked(b) ? "down" : ImGui::IsMouseReleased(b) ? "up" : "";
    if (!*what) continue;
    std::printf("pointer %s %d %.0f %.0f%s%s%s\n", what, b, io.MousePos.x, io.MousePos.y,
                io.KeyShift ? " shift" : "", io.KeyCtrl ? " ctrl" : "", io.KeyAlt ? " alt" : "");
  }
  const bool held = io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2];
  if (held && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0))
    std::printf("pointer at %.0f %.0f\n", io.MousePos.x, io.MousePos.y);
  if (io.WantTextInput != debug_.text_input) {
    debug_.text_input = io.WantTextInput;
    std::printf("text-input %d\n", int(io.WantTextInput));
  }
  // F1's window: its drawing (last frame) says whether it has the keyboard focus.
  const bool help_focused = model_.show_help && esc_closes_ == &model_.show_help;
  if (model_.show_help != debug_.help || help_focused != debug_.help_focused) {
    debug_.help = model_.show_help;
    debug_.help_focused = help_focused;
    std::printf("help-window %d%s\n", int(model_.show_help), help_focused ? " focused" : "");
  }
  const std::string message = model_.status().message();
  if (message != debug_.message) {
    debug_.message = message;
    if (!message.empty()) std::printf("status %s\n", message.c_str());
  }
  std::fflush(stdout);

  const Document& doc = model_.session().doc();
  if (held || frames_ < 3 || !model_.views().ready() || !model_.views().settled() || doc.dragging())
    return;
  const Scene& scene = doc.scene();
  const auto rects = model_.layout().panels(model_.views().panels());
  const Camera& camera = model_.nav().camera();
  const Network none;
  const Network& net = scene.network ? *scene.network : none;
  std::ostringstream out;
  out << "state revision " << doc.revision() << " vertices " << net.vertices.size() << " edges "
      << net.edges.size() << " faces " << net.faces.size() << " curves " << scene.curves.size()
      << " selected " << model_.selection().size() << " can-undo " << doc.can_undo() << " can-redo "
      << doc.can_redo() << " keys " << int(takes_shortcuts()) << " tool "
      << model_.tools().active().name() << "\n";
  const auto [wx, wy] = window_.position();
  out << "view";
  for (const Vec3& p : {Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
    out << " " << pixel(project_to_window(camera, rects[0], p));
  out << " window " << wx << " " << wy << "\n";
  for (std::size_t v = 0; v < net.vertices.size(); ++v)
    out << "vertex " << v << " " << pixel(project_to_window(camera, rects[0], net.vertices[v]))
        << "\n";
  for (std::size_t c = 0; c < scene.curves.size(); ++c)
    for (std::size_t k = 0; k < scene.curves[c].points.size(); ++k)
      out << "curve-point " << c << " " << k << " "
          << pixel(project_to_window(camera, rects[0], scene.curves[c].points[k])) << "\n";
  std::vector<SelectionItem> items;
  const PickScene picks = model_.pick_scene(0, items);
  const DisplaySettings& d = model_.prefs().display;
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    out << "edge " << e << " "
        << pixel(find_pixel_for(model_.picker(0), picks, camera, rects[0],
                                SelectionItem::edge(int(e)), {d.control_net, d.network_curves}))
        << "\n";
  for (std::size_t c = 0; c < scene.curves.size(); ++c)
    out << "curve " << c << " "
        << pixel(find_pixel_for(model_.picker(0), picks, camera, rects[0],
                                SelectionItem::curve(int(c)), {d.control_net, d.network_curves}))
        << "\n";
  // The joints as the view labels them (CurveMarks follows the document every frame).
  for (const JointReport& j : model_.curve_marks().joints())
    out << "joint " << j.curves[0] << " " << j.curves[1] << " "
        << joint_class(j, model_.curve_marks().size()) << " gap " << j.gap << " angle "
        << j.tangent_angle_deg << " jump " << j.curvature_jump << "\n";
  for (std::size_t f = 0; f < net.faces.size(); ++f)
    out << "face " << f << " "
        << pixel(find_pixel_for(model_.picker(0), picks, camera, rects[0],
                                SelectionItem::face(int(f)), {d.control_net, d.network_curves}))
        << "\n";
  if (model_.views().ready()) {
    const ScenePoints& points = model_.views().main()->shown().points();
    for (std::size_t i = 0; i < points.positions.size(); ++i) {
      const auto& r = points.refs[i];
      if (!r || r->kind != PointRef::Kind::FreePoint || !points.shown(i)) continue;
      out << "free-point " << r->object << " "
          << (r->index < 0 ? std::string("centre")
                           : std::to_string(r->index) + "," + std::to_string(r->j) + "," +
                                 std::to_string(r->layer))
          << " " << pixel(project_to_window(camera, rects[0], points.positions[i])) << "\n";
    }
  }
  if (model_.tools().active_index() == 0)
    for (const PlaneHandle& h :
         plane_handles(scene, model_.selection(), camera, rects[0], ui_scale_))
      out << "knob " << h.vertex << " " << pixel(project_to_window(camera, rects[0], h.knob))
          << "\n";
  const std::string state = out.str();
  if (state == debug_.state) return;
  debug_.state = state;
  std::cout << state << "state-end " << doc.revision() << std::endl;
}

}  // namespace pl
