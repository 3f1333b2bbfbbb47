// Keys and mouse: a key press runs the action bound to it; in the view, what lies under the
// cursor is picked every frame, a left press goes to the active tool (or orbits when the tool
// leaves it), right and middle drags pan, a right click opens the context menu on what was
// under the cursor, the wheel zooms.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "app/editor/action_menus.hpp"
#include "app/editor/editor.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/glfw_keys.hpp"
#include "app/editor/logic/selection_properties.hpp"

namespace pl {

std::vector<HelpRow> mouse_help() {
  return {
      {"Click", "select a point, curve (edge) or surface (face); Shift adds, Ctrl toggles"},
      {"Click on empty space", "clear the selection"},
      {"Drag a point", "move the selected points in the view plane"},
      {"  ... holding X / Y / Z", "move along that axis"},
      {"  ... a handle", "it stays in its vertex's tangent plane (G1 kept)"},
      {"  ... a handle holding Alt", "it moves freely; its vertex's tangent plane turns with it"},
      {"Drag a normal's knob", "turn the selected vertex's tangent plane (the disc)"},
      {"Click (Add Vertex)", "a vertex on the surface under the cursor, else on the work plane"},
      {"Click, click (Add Edge)", "an edge between the two vertices; the chain goes on"},
      {"Clicks, Enter (Make Face)", "a face on the vertices (or edges) clicked"},
      {"Click a curve (Split Edge)", "split its edge there"},
      {"Left-drag elsewhere", "orbit (turntable; about the selection if any)"},
      {"Right- or middle-drag", "pan"},
      {"Right-click", "what can be done with the object under the cursor"},
      {"Wheel", "zoom towards the cursor"},
      {"Drop a file on the window", "open it (.json, .gbp)"},
  };
}

std::optional<Vec3> Editor::held_axis() const {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeysDown[GLFW_KEY_X]) return Vec3(1, 0, 0);
  if (io.KeysDown[GLFW_KEY_Y]) return Vec3(0, 1, 0);
  if (io.KeysDown[GLFW_KEY_Z] && !io.KeyCtrl) return Vec3(0, 0, 1);
  return std::nullopt;
}

Vec3 Editor::orbit_pivot() const {
  // About the selection when there is one (what the user is working on), else the scene.
  const Box sel = selection_bounds(session_.doc().scene(), selection_);
  if (!sel.empty()) return sel.centre();
  const Box all = scene_box();
  return all.empty() ? nav_.camera().target : all.centre();
}

void Editor::nudge_selection(const KeyChord& k) {
  const std::vector<PointRef> points = selection_.points();
  if (points.empty() || session_.doc().dragging()) return;
  // Steps are 1% of the scene size (Shift: 10x, Alt: 0.1x): arrows in the view plane, Page
  // Up/Down along the view direction.
  const Camera& c = nav_.camera();
  const double step =
      0.01 * std::max(c.scene_radius, 1e-9) * (k.shift ? 10.0 : 1.0) * (k.alt ? 0.1 : 1.0);
  Vec3 d(0);
  switch (k.key) {
    case Key::Left:
      d = -step * c.right();
      break;
    case Key::Right:
      d = step * c.right();
      break;
    case Key::Up:
      d = step * c.up();
      break;
    case Key::Down:
      d = -step * c.up();
      break;
    case Key::PageUp:
      d = -step * c.forward();
      break;
    case Key::PageDown:
      d = step * c.forward();
      break;
    default:
      return;
  }
  const Scene& scene = session_.doc().scene();
  std::vector<Vec3> positions;
  for (const PointRef& r : points) positions.push_back(point_position(scene, r) + d);
  // Consecutive nudges of the same points are one undo step; handles stay in their planes.
  run_command(
      session_.doc(), [this](const std::string& m) { status_.say(m); },
      std::make_shared<MovePointsCommand>(points, positions, HandleMode::KeepPlane, true));
}

void Editor::escape() {
  ToolContext ctx = tool_context();
  if (tools_.active().capturing() || session_.doc().dragging()) {
    tools_.active().cancel(ctx);
    session_.doc().cancel_drag();
    mouse_.tool_has_it = false;
  } else if (tools_.active_index() != 0) {
    tools_.activate(0, ctx);
  } else {
    selection_.clear();
  }
}

// A text field or a popup (menu, dialog) owns the keyboard; shortcuts pressed meanwhile are
// dropped, not kept for later.
bool Editor::takes_shortcuts() const {
  return !ImGui::GetIO().WantTextInput && !ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId);
}

void Editor::handle_keys() {
  if (!takes_shortcuts()) return;
  for (const auto& [key, mods] : key_presses_) {
    const KeyChord chord = chord_from_glfw(key, mods);
    if (chord.key == Key::None) continue;
    // A slider or field being edited keeps the plain keys; Ctrl chords still work.
    if (!chord.ctrl && ImGui::IsAnyItemActive()) continue;
    actions_.trigger(chord);
    // The next key may act on the selection: drop what an undo removed, or all of it for a new
    // document.
    if (session_.serial() != session_serial_)
      after_document_replaced();
    else
      follow_structure();
  }
}

PointerEvent Editor::pointer_event(const ViewRect& rect, const PickResult* under) const {
  const ImGuiIO& io = ImGui::GetIO();
  PointerEvent e;
  e.pixel = Vec2(io.MousePos.x, io.MousePos.y);
  e.rect = rect;
  e.shift = io.KeyShift;
  e.ctrl = io.KeyCtrl;
  e.alt = io.KeyAlt;
  e.axis = held_axis();
  e.under = under;
  return e;
}

void Editor::handle_mouse() {
  ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  const EditorLayout l = layout();
  const auto rects = l.panels(views_.panels());
  ToolContext ctx = tool_context();

  // A tool that took the press owns the mouse until the release, wherever the cursor goes; no
  // hover or probe meanwhile.
  if (mouse_.tool_has_it || nav_.gesture() != ViewNavigator::Gesture::None) {
    mouse_.under = {};
    mouse_.probe.reset();
  }
  if (mouse_.tool_has_it) {
    const ViewRect& rect = rects[std::clamp(mouse_.pressed_panel, 0, int(rects.size()) - 1)];
    const PointerEvent e = pointer_event(rect, &mouse_.pressed);
    if (!io.MouseDown[0]) {
      tools_.active().release(ctx, e);
      mouse_.tool_has_it = false;
      release_time_ = Clock::now();
    } else {
      tools_.active().drag(ctx, e);
    }
    return;
  }
  // So does a camera gesture; a press and release without motion is a click.
  if (nav_.gesture() != ViewNavigator::Gesture::None) {
    const ViewRect& rect = rects[std::clamp(mouse_.pressed_panel, 0, int(rects.size()) - 1)];
    nav_.move(mouse, rect);
    if (!io.MouseDown[0] && !io.MouseDown[1] && !io.MouseDown[2]) {
      const bool was_orbit = nav_.gesture() == ViewNavigator::Gesture::Orbit;
      if (nav_.end()) {
        if (was_orbit) {
          tools_.active().click(ctx, pointer_event(rect, &mouse_.pressed));
        } else if (mouse_.context_press) {
          // Right-click: the menu acts on the selection, so an unselected object under the
          // cursor becomes the selection first (a selected one keeps the selection as it is).
          const auto& item = mouse_.pressed.item;
          if (item && !selection_.contains(*item)) selection_.set({*item});
          context_ = !item                                      ? ContextTarget::Empty
                     : item->kind == SelectionItem::Kind::Edge  ? ContextTarget::Edge
                     : item->kind == SelectionItem::Kind::Face  ? ContextTarget::Face
                     : item->kind == SelectionItem::Kind::Patch ? ContextTarget::Patch
                     : item->kind == SelectionItem::Kind::Curve ? ContextTarget::Curve
                                                                : ContextTarget::Point;
          open_context_menu();
          debug_.menu_frames = 0;
        }
      }
      mouse_.context_press = false;
    }
    return;
  }

  mouse_.panel = l.panel_at(mouse, views_.panels());
  mouse_.under = {};
  mouse_.probe.reset();
  if (mouse_.panel < 0 || io.WantCaptureMouse || !views_.ready()) {
    mouse_.panel = -1;
    tools_.active().leave();
    return;
  }
  const ViewRect& rect = rects[mouse_.panel];
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(mouse_.panel, items);
  const DisplaySettings& d = prefs_.display;
  mouse_.under = pickers_[mouse_.panel].pick(scene, nav_.camera(), rect, mouse,
                                             {d.control_net, d.network_curves});
  // The probe reads the surface itself: over a point or a curve it would hide what is picked.
  if (prefs_.show_probe && mouse_.under.point < 0 && mouse_.under.edge < 0 &&
      mouse_.under.surface) {
    const SurfaceHit& h = *mouse_.under.surface;
    mouse_.probe =
        probe_at(scene.meshes[h.surface], h.surface, h.hit, window_ray(nav_.camera(), rect, mouse));
  }

  tools_.active().hover(ctx, pointer_event(rect, &mouse_.under));
  nav_.wheel(rect, mouse, io.MouseWheel);

  const bool left = ImGui::IsMouseClicked(0), right = ImGui::IsMouseClicked(1),
             middle = ImGui::IsMouseClicked(2);
  if (!left && !right && !middle) return;
  mouse_.pressed = mouse_.under;
  mouse_.pressed_panel = mouse_.panel;
  mouse_.pressed_point.reset();
  mouse_.pressed_placement = placement(ctx, pointer_event(rect, &mouse_.pressed));
  if (mouse_.under.point >= 0)
    mouse_.pressed_point = scene.points->positions[mouse_.under.point];
  else if (mouse_.under.curve >= 0)
    mouse_.pressed_point = mouse_.under.curve_point;  // where a curve action acts
  else if (mouse_.under.surface)
    mouse_.pressed_point = mouse_.under.surface->position;
  if (left) {
    if (tools_.active().press(ctx, pointer_event(rect, &mouse_.pressed)))
      mouse_.tool_has_it = true;
    else
      nav_.begin(ViewNavigator::Gesture::Orbit, mouse, orbit_pivot(), orbit_sample(shown_scenes()));
  } else {
    nav_.begin(ViewNavigator::Gesture::Pan, mouse, Vec3(0));
    mouse_.context_press = right;
  }
}

}  // namespace pl
