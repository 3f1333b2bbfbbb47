// GLFW and ImGui input to the editor model's events: the key presses of the frame as chords
// (unless a text field or popup has the keyboard), the pointer as the frame saw it; and the
// mouse's lines of the help.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "app/editor/editor.hpp"
#include "app/editor/editor_windows.hpp"
#include "app/editor/glfw_keys.hpp"

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
      {"Drop a file on the window", "open it (.json, .gbp; curves from .obj, .step, .igs)"},
  };
}

// A text field or a popup (menu, dialog) owns the keyboard; shortcuts pressed meanwhile are
// dropped, not kept for later.
bool Editor::takes_shortcuts() const {
  return !ImGui::GetIO().WantTextInput && !ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId);
}

void Editor::send_keys() {
  if (!takes_shortcuts()) return;
  for (const auto& [key, mods] : key_presses_) {
    const KeyChord chord = chord_from_glfw(key, mods);
    if (chord.key == Key::None) continue;
    // A slider or field being edited keeps the plain keys; Ctrl chords still work.
    if (!chord.ctrl && ImGui::IsAnyItemActive()) continue;
    // Esc closes the focused window (F1's help, the curvature graph) and does nothing else: the
    // selection behind it is not what the user is looking at.
    if (chord == KeyChord{Key::Escape} && esc_closes_) {
      *esc_closes_ = false;
      esc_closes_ = nullptr;
      continue;
    }
    model_.key(chord);
  }
}

PointerInput Editor::pointer_input() const {
  const ImGuiIO& io = ImGui::GetIO();
  PointerInput in;
  in.pixel = Vec2(io.MousePos.x, io.MousePos.y);
  for (int b = 0; b < 3; ++b) {
    in.down[b] = io.MouseDown[b];
    in.pressed[b] = ImGui::IsMouseClicked(b);
  }
  in.wheel = io.MouseWheel;
  in.shift = io.KeyShift;
  in.ctrl = io.KeyCtrl;
  in.alt = io.KeyAlt;
  // X, Y or Z held: a drag along that axis (Ctrl+Z is undo, not an axis).
  if (io.KeysDown[GLFW_KEY_X])
    in.axis = Vec3(1, 0, 0);
  else if (io.KeysDown[GLFW_KEY_Y])
    in.axis = Vec3(0, 1, 0);
  else if (io.KeysDown[GLFW_KEY_Z] && !io.KeyCtrl)
    in.axis = Vec3(0, 0, 1);
  in.over_interface = io.WantCaptureMouse;
  return in;
}

}  // namespace pl
