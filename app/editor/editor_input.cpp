// Mouse and keyboard: camera moves, picking, dragging, nudging and the global shortcuts.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/editor/editor.hpp"
#include "app/editor/logic/camera_control.hpp"

namespace pl {

namespace {

// Pixels within which a control point counts as under the cursor.
constexpr double kPickRadiusPx = 9.0;
// Mouse-wheel zoom factor per notch.
constexpr double kWheelZoom = 1.15;
// A press and release closer than this is a click, not an orbit.
constexpr float kClickSlopPx = 3.0f;

Box box_of(const DrawScene& d) {
  return d.bounds();
}

}  // namespace

std::optional<Vec3> Editor::held_axis() const {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.KeysDown[GLFW_KEY_X]) return Vec3(1, 0, 0);
  if (io.KeysDown[GLFW_KEY_Y]) return Vec3(0, 1, 0);
  if (io.KeysDown[GLFW_KEY_Z] && !io.KeyCtrl) return Vec3(0, 0, 1);
  return std::nullopt;
}

Vec3 Editor::orbit_pivot() const {
  // About the selection when there is one (what the user is working on), else the scene.
  if (!selection_.empty()) {
    Vec3 c(0);
    int n = 0;
    for (const PointRef& r : selection_)
      if (point_exists(doc_.scene(), r)) c += point_position(doc_.scene(), r), ++n;
    if (n) return c / double(n);
  }
  if (main_view_) {
    const Box b = box_of(main_view_->shown().draw());
    if (!b.empty()) return b.centre();
  }
  return camera_.target;
}

void Editor::frame_all() {
  if (!main_view_) return;
  const auto rects = panel_rects();
  camera_.frame(box_of(main_view_->shown().draw()), rects[0].aspect());
  camera_framed_ = true;
}

void Editor::frame_selection() {
  if (selection_.empty()) return frame_all();
  Box b;
  for (const PointRef& r : selection_)
    if (point_exists(doc_.scene(), r)) b.add(point_position(doc_.scene(), r));
  if (b.empty()) return;
  const double keep_radius = camera_.scene_radius;  // clipping planes stay sized for the scene
  Box grown = b;
  const double r = std::max(b.radius(), 0.08 * keep_radius);
  grown.add(b.centre() + Vec3(r));
  grown.add(b.centre() - Vec3(r));
  camera_.frame(grown, panel_rects()[0].aspect());
  camera_.scene_radius = std::max(keep_radius, camera_.scene_radius);
}

void Editor::set_preset(ViewPreset preset) {
  const bool ortho = camera_.orthographic;
  if (!main_view_) return;
  camera_ =
      preset_camera(preset, box_of(main_view_->shown().draw()), panel_rects()[0].aspect(), ortho);
}

void Editor::nudge_selection(const Vec3& direction) {
  if (selection_.empty() || doc_.dragging()) return;
  std::vector<Vec3> positions;
  for (const PointRef& r : selection_)
    positions.push_back(point_position(doc_.scene(), r) + direction);
  doc_.execute(std::make_unique<MovePointsCommand>(selection_, positions));
}

void Editor::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) return;
  for (const auto& [key, mods] : key_presses_) {
    const bool ctrl = mods & GLFW_MOD_CONTROL, shift = mods & GLFW_MOD_SHIFT,
               alt = mods & GLFW_MOD_ALT;
    if (ctrl) {
      handle_ctrl_key(key, shift);
      continue;
    }
    if (ImGui::IsAnyItemActive()) continue;  // a slider or field being edited has the keys
    // Arrow keys nudge the selection in the view plane; Page Up/Down along the view direction.
    // Steps are 1% of the scene size (Shift: 10x, Alt: 0.1x).
    const double step =
        0.01 * std::max(camera_.scene_radius, 1e-9) * (shift ? 10.0 : 1.0) * (alt ? 0.1 : 1.0);
    switch (key) {
      case GLFW_KEY_F1:
        show_help_ = !show_help_;
        break;
      case GLFW_KEY_F:
        shift ? frame_selection() : frame_all();
        break;
      case GLFW_KEY_C:
        if (doc_.scene().network) {
          compare_ = !compare_;
          rebuild_views();
          frame_all();  // the panels' aspect changed
        }
        break;
      case GLFW_KEY_D:
        if (compare_) difference_ = !difference_;
        break;
      case GLFW_KEY_1:
        set_preset(ViewPreset::Front);
        break;
      case GLFW_KEY_3:
        set_preset(ViewPreset::Right);
        break;
      case GLFW_KEY_7:
        set_preset(ViewPreset::Top);
        break;
      case GLFW_KEY_0:
        set_preset(ViewPreset::Iso);
        break;
      case GLFW_KEY_5:
        camera_.orthographic = !camera_.orthographic;
        break;
      case GLFW_KEY_ESCAPE:
        if (doc_.dragging()) {
          doc_.cancel_drag();
          point_drag_ = false;
        } else {
          selection_.clear();
        }
        break;
      case GLFW_KEY_LEFT:
        nudge_selection(-step * camera_.right());
        break;
      case GLFW_KEY_RIGHT:
        nudge_selection(step * camera_.right());
        break;
      case GLFW_KEY_UP:
        nudge_selection(step * camera_.up());
        break;
      case GLFW_KEY_DOWN:
        nudge_selection(-step * camera_.up());
        break;
      case GLFW_KEY_PAGE_UP:
        nudge_selection(-step * camera_.forward());
        break;
      case GLFW_KEY_PAGE_DOWN:
        nudge_selection(step * camera_.forward());
        break;
      default:
        break;
    }
  }
}

void Editor::handle_ctrl_key(int key, bool shift) {
  switch (key) {
    case GLFW_KEY_Z:
      shift ? doc_.redo() : doc_.undo();
      point_drag_ = false;
      break;
    case GLFW_KEY_Y:
      doc_.redo();
      point_drag_ = false;
      break;
    case GLFW_KEY_S:
      if (shift || doc_.path().empty()) {
        browse_for_ = BrowseFor::SaveAs;
        browser_.open("Save scene as", "Save", browse_start_dir(), {".json"}, ".json",
                      doc_.path().filename().string());
      } else {
        save();
      }
      break;
    case GLFW_KEY_O:
      confirm_discard("open another file", [this] {
        browse_for_ = BrowseFor::Open;
        browser_.open("Open scene", "Open", browse_start_dir(), {".json", ".gbp"}, "");
      });
      break;
    case GLFW_KEY_Q:
      confirm_discard("quit", [this] { quit_ = true; });
      break;
    default:
      break;
  }
}

void Editor::begin_point_drag(const ViewRect& rect) {
  std::vector<PointRef> points;
  for (const PointRef& r : selection_)
    if (point_exists(doc_.scene(), r)) points.push_back(r);
  if (points.empty() || !hover_) return;
  drag_start_positions_.clear();
  for (const PointRef& r : points) drag_start_positions_.push_back(point_position(doc_.scene(), r));
  drag_last_positions_ = drag_start_positions_;
  const ImGuiIO& io = ImGui::GetIO();
  drag_motion_ = {point_position(doc_.scene(), *hover_), Vec2(io.MousePos.x, io.MousePos.y)};
  drag_rect_ = rect;
  doc_.begin_drag(points);
  point_drag_ = true;
}

void Editor::handle_viewport_mouse() {
  ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse(io.MousePos.x, io.MousePos.y);
  const int panel = panel_at(mouse);
  const auto rects = panel_rects();

  // A drag in progress owns the mouse until release, wherever the cursor goes.
  if (point_drag_) {
    if (!doc_.dragging()) {
      point_drag_ = false;  // undone or cancelled meanwhile
      return;
    }
    // The cursor's last position counts even when the release arrived in the same frame.
    const Vec3 d = drag_motion_.offset(camera_, drag_rect_, mouse, held_axis());
    std::vector<Vec3> positions = drag_start_positions_;
    for (Vec3& p : positions) p += d;
    // Only real motion is an edit: each drag_to bumps the document's revision.
    if (positions != drag_last_positions_) {
      doc_.drag_to(positions);
      drag_last_positions_ = positions;
    }
    if (!io.MouseDown[0]) {
      doc_.end_drag();
      point_drag_ = false;
      release_time_ = Clock::now();
    }
    return;
  }
  if (camera_drag_ != CameraDrag::None) {
    const Vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
    if (camera_drag_ == CameraDrag::Orbit)
      orbit_about(camera_, orbit_pivot_at_press_, -delta.x * kOrbitRadiansPerPixel,
                  delta.y * kOrbitRadiansPerPixel);
    else
      pan_pixels(camera_, rects[0], delta.x, delta.y);
    if (!io.MouseDown[0] && !io.MouseDown[1] && !io.MouseDown[2]) {
      // A plain click on empty space (no orbit motion) clears the selection.
      if (camera_drag_ == CameraDrag::Orbit && clear_on_click_ &&
          io.MouseDragMaxDistanceSqr[0] < kClickSlopPx * kClickSlopPx)
        selection_.clear();
      camera_drag_ = CameraDrag::None;
    }
    return;
  }

  hover_.reset();
  hover_derived_ = -1;
  probe_.reset();
  if (panel < 0 || io.WantCaptureMouse || !main_view_) return;
  const ViewRect& rect = rects[panel];
  const EvaluatedView& view = panel_view(panel);
  const ScenePoints& pts = view.shown().points();
  if (prefs_.display.control_net) {
    // Editable points first: a derived point next to a vertex must not block grabbing it.
    const int i = pick_point(camera_, rect, pts.positions, pts.editable(), mouse, kPickRadiusPx);
    if (i >= 0)
      hover_ = pts.refs[i];
    else
      hover_derived_ = pick_point(camera_, rect, pts.positions, {}, mouse, kPickRadiusPx);
  }
  if (prefs_.show_probe && !hover_) {
    const auto& meshes = view.shown().draw().surfaces;
    probe_ = probe_surfaces(meshes, window_ray(camera_, rect, mouse));
  }

  if (io.MouseWheel != 0)
    zoom_at(camera_, rect, mouse, std::pow(kWheelZoom, static_cast<double>(io.MouseWheel)));

  if (ImGui::IsMouseClicked(0)) {
    if (hover_ && !io.KeyAlt) {
      const bool selected =
          std::find(selection_.begin(), selection_.end(), *hover_) != selection_.end();
      if (io.KeyShift) {
        if (!selected) selection_.push_back(*hover_);
      } else if (!selected) {
        selection_ = {*hover_};
      }
      begin_point_drag(rect);
    } else {
      clear_on_click_ = !io.KeyShift && !io.KeyAlt;
      camera_drag_ = CameraDrag::Orbit;
      orbit_pivot_at_press_ = orbit_pivot();
    }
  } else if (ImGui::IsMouseClicked(1) || ImGui::IsMouseClicked(2)) {
    camera_drag_ = CameraDrag::Pan;
  }
}

}  // namespace pl
