#include "app/editor/glfw_keys.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace pl {

Key key_from_glfw(int k) {
  if (k >= GLFW_KEY_A && k <= GLFW_KEY_Z) return static_cast<Key>(int(Key::A) + k - GLFW_KEY_A);
  if (k >= GLFW_KEY_0 && k <= GLFW_KEY_9) return static_cast<Key>(int(Key::Num0) + k - GLFW_KEY_0);
  if (k >= GLFW_KEY_F1 && k <= GLFW_KEY_F12)
    return static_cast<Key>(int(Key::F1) + k - GLFW_KEY_F1);
  switch (k) {
    case GLFW_KEY_ESCAPE:
      return Key::Escape;
    case GLFW_KEY_ENTER:
      return Key::Enter;
    case GLFW_KEY_KP_ENTER:
      return Key::Enter;
    case GLFW_KEY_TAB:
      return Key::Tab;
    case GLFW_KEY_SPACE:
      return Key::Space;
    case GLFW_KEY_BACKSPACE:
      return Key::Backspace;
    case GLFW_KEY_DELETE:
      return Key::Delete;
    case GLFW_KEY_INSERT:
      return Key::Insert;
    case GLFW_KEY_HOME:
      return Key::Home;
    case GLFW_KEY_END:
      return Key::End;
    case GLFW_KEY_LEFT:
      return Key::Left;
    case GLFW_KEY_RIGHT:
      return Key::Right;
    case GLFW_KEY_UP:
      return Key::Up;
    case GLFW_KEY_DOWN:
      return Key::Down;
    case GLFW_KEY_PAGE_UP:
      return Key::PageUp;
    case GLFW_KEY_PAGE_DOWN:
      return Key::PageDown;
    // The numeric keypad's digits act as the row's (view presets 1 3 7 0 5).
    case GLFW_KEY_KP_0:
      return Key::Num0;
    case GLFW_KEY_KP_1:
      return Key::Num1;
    case GLFW_KEY_KP_3:
      return Key::Num3;
    case GLFW_KEY_KP_5:
      return Key::Num5;
    case GLFW_KEY_KP_7:
      return Key::Num7;
    default:
      return Key::None;
  }
}

KeyChord chord_from_glfw(int key, int mods) {
  return {key_from_glfw(key), (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0,
          (mods & GLFW_MOD_ALT) != 0};
}

}  // namespace pl
