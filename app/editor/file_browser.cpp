#include "app/editor/file_browser.hpp"

#include <imgui.h>

#include <cstring>
#include <system_error>
#include <utility>

namespace pl {

namespace fs = std::filesystem;

void FileBrowser::open(const std::string& title, const std::string& action, fs::path dir,
                       std::vector<std::string> extensions, std::string default_extension,
                       std::string name) {
  title_ = title;
  action_ = action;
  dir_ = std::move(dir);
  extensions_ = std::move(extensions);
  default_extension_ = std::move(default_extension);
  std::snprintf(name_, sizeof name_, "%s", name.c_str());
  selected_ = -1;
  problem_.clear();
  open_request_ = true;
  refresh();
}

void FileBrowser::refresh() {
  listing_ = list_directory(dir_, extensions_);
}

std::optional<fs::path> FileBrowser::draw() {
  const std::string id = title_ + "###file_browser";
  if (open_request_) {
    ImGui::OpenPopup(id.c_str());
    open_request_ = false;
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x * 0.55f, vp->Size.y * 0.6f), ImGuiCond_Appearing);
  std::optional<fs::path> chosen;
  if (!ImGui::BeginPopupModal(id.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings)) return chosen;
  if (ImGui::Button("Up") && dir_.has_parent_path()) {
    dir_ = dir_.parent_path();
    refresh();
  }
  ImGui::SameLine();
  if (ImGui::Button("Home"))
    if (const char* home = std::getenv("HOME")) {
      dir_ = home;
      refresh();
    }
  ImGui::SameLine();
  ImGui::TextDisabled("%s", dir_.string().c_str());
  std::string filter;
  for (const std::string& e : extensions_) {
    if (!filter.empty()) filter += ' ';
    filter += '*';
    filter += e;
  }
  const float footer = ImGui::GetFrameHeightWithSpacing() * (problem_.empty() ? 2.2f : 3.2f);
  ImGui::BeginChild("listing", ImVec2(0, -footer), true);
  if (!listing_.error.empty())
    ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", listing_.error.c_str());
  std::optional<fs::path> enter;
  for (int i = 0; i < static_cast<int>(listing_.entries.size()); ++i) {
    const DirEntry& e = listing_.entries[i];
    const std::string label = (e.directory ? "[dir]  " : "       ") + e.name;
    if (ImGui::Selectable(label.c_str(), selected_ == i, ImGuiSelectableFlags_AllowDoubleClick)) {
      selected_ = i;
      if (e.directory) {
        if (ImGui::IsMouseDoubleClicked(0)) enter = dir_ / e.name;
      } else {
        std::snprintf(name_, sizeof name_, "%s", e.name.c_str());
        if (ImGui::IsMouseDoubleClicked(0)) chosen = dir_ / e.name;
      }
    }
  }
  ImGui::EndChild();
  if (enter) {
    dir_ = enter->lexically_normal();
    selected_ = -1;
    refresh();
  }
  // Sizes follow the font, so the dialog reads the same at every UI scale.
  const float button = ImGui::GetFontSize() * 8;
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize(filter.c_str()).x -
                          ImGui::GetStyle().ItemSpacing.x * 2);
  // Type a name straight away, and again after a refused name or a folder typed into the field
  // (Enter left the field).
  if (ImGui::IsWindowAppearing() || std::exchange(refocus_, false)) ImGui::SetKeyboardFocusHere();
  const bool typed_enter = ImGui::InputTextWithHint("##name", "file name", name_, sizeof name_,
                                                    ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", filter.c_str());
  if ((ImGui::Button(action_.c_str(), ImVec2(button, 0)) || typed_enter) && name_[0] != '\0') {
    const fs::path p = resolve_typed_name(dir_, name_, default_extension_);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      dir_ = p;
      name_[0] = '\0';
      refresh();
      refocus_ = true;
    } else if (problem_ = extension_problem(p, extensions_); problem_.empty()) {
      chosen = p;
    } else {
      refocus_ = true;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(button, 0)) ||
      ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
    ImGui::CloseCurrentPopup();
  // A refused name stays in the field to be corrected; the reason is said below it.
  if (!problem_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.5f, 1), "%s", problem_.c_str());
  if (chosen) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  return chosen;
}

}  // namespace pl
