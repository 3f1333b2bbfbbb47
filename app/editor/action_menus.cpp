#include "app/editor/action_menus.hpp"

#include <imgui.h>

namespace pl {

namespace {

constexpr const char* kContextPopup = "##context";

void menu_item(const ActionRegistry& actions, const Action& a, const MenuItemProbe& probe) {
  const std::string shortcut = a.keys.empty() ? std::string() : to_string(a.keys[0]);
  const bool checked = a.checked && a.checked();
  const std::string detail = a.detail ? a.detail() : std::string();
  const std::string label = detail.empty() ? a.label : a.label + " " + detail;
  const bool enabled = actions.is_enabled(a);
  if (ImGui::MenuItem(label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), checked,
                      enabled))
    a.run(std::nullopt);
  if (probe) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    probe(a.label, lo.x, lo.y, hi.x, hi.y);
  }
  // A greyed item says why it does not apply now.
  if (!enabled && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s", actions.disabled_reason(a).c_str());
  else if (!a.help.empty() && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", a.help.c_str());
}

void menu_entries(const ActionRegistry& actions, const std::string& menu) {
  bool first = true;
  for (const ActionRegistry::Entry& e : actions.entries(menu)) {
    if (e.action) {
      if (e.action->separator_before && !first) ImGui::Separator();
      menu_item(actions, *e.action, nullptr);
    } else {
      const std::string name = e.submenu.substr(e.submenu.rfind('/') + 1);
      if (ImGui::BeginMenu(name.c_str())) {
        menu_entries(actions, e.submenu);
        ImGui::EndMenu();
      }
    }
    first = false;
  }
}

}  // namespace

void draw_menu_bar(const ActionRegistry& actions) {
  if (!ImGui::BeginMainMenuBar()) return;
  for (const std::string& menu : actions.menus())
    if (ImGui::BeginMenu(menu.c_str())) {
      menu_entries(actions, menu);
      // Esc closes an open menu, as the context menu (the editor takes no keys meanwhile).
      if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
      ImGui::EndMenu();
    }
  ImGui::EndMainMenuBar();
}

void open_context_menu() {
  ImGui::OpenPopup(kContextPopup);
}

bool draw_context_menu(const ActionRegistry& actions, ContextTarget target,
                       const MenuItemProbe& probe) {
  if (!ImGui::BeginPopup(kContextPopup)) return false;
  // Esc closes it (ImGui leaves that to keyboard navigation, which the editor does not use).
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  const auto offered = actions.for_context(target);
  if (offered.empty()) ImGui::TextDisabled("Nothing to do here");
  std::string group;
  for (const Action* a : offered) {
    // Actions of one menu stay together, headed by its name ("Face/Scheme" -> "Scheme").
    const std::string name = a->menu.substr(a->menu.rfind('/') + 1);
    if (name != group) {
      if (!group.empty()) ImGui::Separator();
      ImGui::TextDisabled("%s", name.c_str());
      group = name;
    }
    menu_item(actions, *a, probe);
  }
  ImGui::EndPopup();
  return true;
}

}  // namespace pl
