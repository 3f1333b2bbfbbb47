// GLFW's key codes and modifier bits as the action table's keys.
#pragma once

#include "app/editor/logic/actions.hpp"

namespace pl {

Key key_from_glfw(int key);  // Key::None for keys the table cannot bind
KeyChord chord_from_glfw(int key, int mods);

}  // namespace pl
