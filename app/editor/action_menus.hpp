// The menu bar and the right-click context menu, both drawn from the action table: an action's
// menu path places it, its first key is shown beside it, a toggle gets a check mark, a disabled
// one is greyed. ImGui code; what the actions do is the table's.
#pragma once

#include <functional>
#include <string>

#include "app/editor/logic/actions.hpp"

namespace pl {

// Called with each item's label and window rectangle (x0, y0, x1, y1) as it is drawn, for
// scripts that click menu items (the editor's debug output).
using MenuItemProbe = std::function<void(const std::string&, float, float, float, float)>;

void draw_menu_bar(const ActionRegistry& actions);
// Opens the context menu on the next draw_context_menu().
void open_context_menu();
// Draws the context menu while it is open, with the actions offered on `target`. Returns false
// once it has closed.
bool draw_context_menu(const ActionRegistry& actions, ContextTarget target,
                       const MenuItemProbe& probe = nullptr);

}  // namespace pl
