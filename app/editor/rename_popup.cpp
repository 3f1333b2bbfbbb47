#include "app/editor/rename_popup.hpp"

#include <imgui.h>

#include <cstdio>

namespace pl {

namespace {

constexpr const char* kPopup = "##rename";

}  // namespace

void RenamePopup::open(const SelectionItem& item, const std::string& name) {
  item_ = item;
  std::snprintf(name_, sizeof name_, "%s", name.c_str());
  open_request_ = true;
}

std::optional<std::pair<SelectionItem, std::string>> RenamePopup::draw(float s) {
  if (open_request_) {
    ImGui::OpenPopup(kPopup);
    open_request_ = false;
  }
  std::optional<std::pair<SelectionItem, std::string>> done;
  if (!ImGui::BeginPopup(kPopup)) return done;
  ImGui::Text("Rename %s", describe(item_).c_str());
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();  // type at once
  ImGui::SetNextItemWidth(260 * s);
  if (ImGui::InputText("##name", name_, sizeof name_,
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    done = std::make_pair(item_, std::string(name_));
    ImGui::CloseCurrentPopup();
  }
  ImGui::TextDisabled("Enter: apply   Esc: leave it");
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return done;
}

}  // namespace pl
