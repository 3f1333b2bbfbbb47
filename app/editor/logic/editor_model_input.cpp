// Keys and the pointer: a key chord runs the action bound to it; in the view, what lies under the
// cursor is picked every frame, a left press goes to the active tool (or orbits when the tool
// leaves it), right and middle drags pan, a right click opens the context menu on what was under
// the cursor, the wheel zooms.
#include <algorithm>

#include "app/editor/logic/editor_model.hpp"
#include "app/editor/logic/selection_properties.hpp"

namespace pl {

Vec3 EditorModel::orbit_pivot() const {
  // About the selection when there is one (what the user is working on), else the scene.
  const Box sel = selection_bounds(session_.doc().scene(), selection_);
  if (!sel.empty()) return sel.centre();
  const Box all = scene_box();
  return all.empty() ? nav_.camera().target : all.centre();
}

void EditorModel::nudge_selection(const KeyChord& k) {
  const std::vector<PointRef> points = selection_.points();
  if (points.empty() || session_.doc().dragging()) return;
  // Steps are 1% of the scene size (Shift: 10x, Alt: 0.1x): arrows in the view plane, Page
  // Up/Down along the view direction.
  const Camera& c = nav_.camera();
  const double step =
      0.01 * std::max(c.scene_radius, 1e-9) * (k.shift ? 10.0 : 1.0) * (k.alt ? 0.1 : 1.0);
  const std::pair<Key, Vec3> directions[] = {
      {Key::Left, -c.right()}, {Key::Right, c.right()},     {Key::Up, c.up()},
      {Key::Down, -c.up()},    {Key::PageUp, -c.forward()}, {Key::PageDown, c.forward()}};
  const auto it = std::find_if(std::begin(directions), std::end(directions),
                               [&](const auto& kd) { return kd.first == k.key; });
  if (it == std::end(directions)) return;
  const Vec3 d = step * it->second;
  const Scene& scene = session_.doc().scene();
  std::vector<Vec3> positions;
  for (const PointRef& r : points) positions.push_back(point_position(scene, r) + d);
  // Consecutive nudges of the same points are one undo step; handles stay in their planes.
  run_command(
      session_.doc(), [this](const std::string& m) { say(m); },
      std::make_shared<MovePointsCommand>(points, positions, HandleMode::KeepPlane, true));
}

void EditorModel::escape() {
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

void EditorModel::key(const KeyChord& chord) {
  follow_session();
  if (chord.key == Key::None) return;
  // A key whose command does not apply now says why, instead of doing nothing unexplained.
  actions_.trigger(chord, [this](const std::string& why) { say(why); });
  // The next key may act on the selection: drop what an undo removed, or all of it for a new
  // document.
  if (session_.serial() != session_serial_)
    after_document_replaced();
  else
    follow_structure();
}

PointerEvent EditorModel::pointer_event(const PointerInput& in, const ViewRect& rect,
                                        const PickResult* under) const {
  PointerEvent e;
  e.pixel = in.pixel;
  e.rect = rect;
  e.shift = in.shift;
  e.ctrl = in.ctrl;
  e.alt = in.alt;
  e.axis = in.axis;
  e.under = under;
  return e;
}

// A tool that took the press owns the pointer until the release, wherever the cursor goes.
void EditorModel::pointer_held(const PointerInput& in, const std::vector<ViewRect>& rects) {
  ToolContext ctx = tool_context();
  const ViewRect& rect = rects[std::clamp(mouse_.pressed_panel, 0, int(rects.size()) - 1)];
  const PointerEvent e = pointer_event(in, rect, &mouse_.pressed);
  if (!in.down[0]) {
    tools_.active().release(ctx, e);
    mouse_.tool_has_it = false;
    release_time_ = Clock::now();
  } else {
    tools_.active().drag(ctx, e);
  }
}

// So does a camera gesture; a press and release without motion is a click.
void EditorModel::gesture(const PointerInput& in, const std::vector<ViewRect>& rects) {
  const ViewRect& rect = rects[std::clamp(mouse_.pressed_panel, 0, int(rects.size()) - 1)];
  nav_.move(in.pixel, rect);
  if (in.down[0] || in.down[1] || in.down[2]) return;
  const bool was_orbit = nav_.gesture() == ViewNavigator::Gesture::Orbit;
  if (nav_.end()) {
    if (was_orbit) {
      ToolContext ctx = tool_context();
      tools_.active().click(ctx, pointer_event(in, rect, &mouse_.pressed));
    } else if (mouse_.context_press) {
      open_context_menu();
    }
  }
  mouse_.context_press = false;
}

void EditorModel::open_context_menu() {
  // The menu acts on the selection, so an unselected object under the cursor becomes the
  // selection first (a selected one keeps the selection as it is).
  const auto& item = mouse_.pressed.item;
  if (item && !selection_.contains(*item)) selection_.set({*item});
  context_ = !item                                      ? ContextTarget::Empty
             : item->kind == SelectionItem::Kind::Edge  ? ContextTarget::Edge
             : item->kind == SelectionItem::Kind::Face  ? ContextTarget::Face
             : item->kind == SelectionItem::Kind::Patch ? ContextTarget::Patch
             : item->kind == SelectionItem::Kind::Curve ? ContextTarget::Curve
                                                        : ContextTarget::Point;
  ++context_serial_;
}

void EditorModel::pointer(const PointerInput& in) {
  follow_session();
  const EditorLayout l = layout();
  const auto rects = l.panels(views_.panels());
  // No hover or probe while a tool or a gesture holds the pointer.
  if (mouse_.tool_has_it || nav_.gesture() != ViewNavigator::Gesture::None) {
    mouse_.under = {};
    mouse_.probe.reset();
  }
  if (mouse_.tool_has_it) return pointer_held(in, rects);
  if (nav_.gesture() != ViewNavigator::Gesture::None) return gesture(in, rects);

  mouse_.panel = l.panel_at(in.pixel, views_.panels());
  mouse_.under = {};
  mouse_.probe.reset();
  if (mouse_.panel < 0 || in.over_interface || !views_.ready()) {
    mouse_.panel = -1;
    tools_.active().leave();
    return;
  }
  const ViewRect& rect = rects[mouse_.panel];
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(mouse_.panel, items);
  const DisplaySettings& d = prefs_.display;
  mouse_.under = pickers_[mouse_.panel].pick(scene, nav_.camera(), rect, in.pixel,
                                             {d.control_net, d.network_curves});
  // The probe reads the surface itself: over a point or a curve it would hide what is picked.
  if (prefs_.show_probe && mouse_.under.point < 0 && mouse_.under.edge < 0 &&
      mouse_.under.surface) {
    const SurfaceHit& h = *mouse_.under.surface;
    mouse_.probe = probe_at(scene.meshes[h.surface], h.surface, h.hit,
                            window_ray(nav_.camera(), rect, in.pixel));
  }

  ToolContext ctx = tool_context();
  tools_.active().hover(ctx, pointer_event(in, rect, &mouse_.under));
  nav_.wheel(rect, in.pixel, in.wheel);

  const bool left = in.pressed[0], right = in.pressed[1], middle = in.pressed[2];
  if (!left && !right && !middle) return;
  mouse_.pressed = mouse_.under;
  mouse_.pressed_panel = mouse_.panel;
  mouse_.pressed_point.reset();
  mouse_.pressed_placement = placement(ctx, pointer_event(in, rect, &mouse_.pressed));
  if (mouse_.under.point >= 0)
    mouse_.pressed_point = scene.points->positions[mouse_.under.point];
  else if (mouse_.under.curve >= 0)
    mouse_.pressed_point = mouse_.under.curve_point;  // where a curve action acts
  else if (mouse_.under.surface)
    mouse_.pressed_point = mouse_.under.surface->position;
  if (left) {
    if (tools_.active().press(ctx, pointer_event(in, rect, &mouse_.pressed)))
      mouse_.tool_has_it = true;
    else
      nav_.begin(ViewNavigator::Gesture::Orbit, in.pixel, orbit_pivot(),
                 orbit_sample(shown_scenes()));
  } else {
    nav_.begin(ViewNavigator::Gesture::Pan, in.pixel, Vec3(0));
    mouse_.context_press = right;
  }
}

}  // namespace pl
