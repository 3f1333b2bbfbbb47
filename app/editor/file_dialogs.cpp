#include "app/editor/file_dialogs.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <iostream>

#include "app/document/scene_file.hpp"

namespace pl {

void FileDialogs::browse(Purpose purpose, const std::filesystem::path& dir,
                         const std::string& name) {
  purpose_ = purpose;
  switch (purpose) {
    case Purpose::Open:
      browser_.open("Open scene", "Open", dir, openable_extensions(), "");
      break;
    case Purpose::SaveAs:
      // The types Open lists; a .gbp holds a single GB patch (a scene that is one is saved back).
      browser_.open("Save scene as", "Save", dir, {".json", ".gbp"}, ".json", name);
      break;
    case Purpose::Export:
      browser_.open("Export", "Export", dir,
                    {".obj", ".ply", ".off", ".stl", ".step", ".stp", ".igs", ".iges"}, ".obj",
                    name);
      break;
    case Purpose::Screenshot:
      browser_.open("Save screenshot", "Save", dir, {".png"}, ".png", name);
      break;
  }
}

void FileDialogs::browse_export(const std::filesystem::path& dir, const std::string& stem,
                                const ExportFormat* format) {
  purpose_ = Purpose::Export;
  std::vector<std::string> extensions;
  for (const ExportFormat& f : export_formats())
    if (!format || &f == format)
      extensions.insert(extensions.end(), f.extensions.begin(), f.extensions.end());
  const std::string ext = format ? format->extensions.front() : ".obj";
  browser_.open(format ? "Export " + format->label : "Export", "Export", dir, extensions, ext,
                stem + ext);
}

void FileDialogs::browse_save_as() {
  auto [dir, name] = handlers_.save_as_start();
  browse(Purpose::SaveAs, dir, name);
}

void FileDialogs::show_report(const std::string& title, const std::string& text) {
  report_title_ = title;
  report_text_ = text;
  report_request_ = true;
}

void FileDialogs::offer_recovery(RecoveryOffer offer) {
  recovery_ = std::move(offer);
  recovery_request_ = true;
}

void FileDialogs::show_error(const std::string& title, const std::string& message) {
  error_title_ = title;
  error_message_ = message;
  error_request_ = true;
  after_save_ = nullptr;  // whatever waited for a save does not happen
  std::cerr << "patchlab: " << message << "\n";
}

void FileDialogs::confirm_discard(const std::string& what, std::function<void()> action) {
  if (!handlers_.dirty()) {
    action();
    return;
  }
  confirm_what_ = what;
  confirm_action_ = std::move(action);
  confirm_request_ = true;
}

void FileDialogs::saved() {
  if (after_save_ && !handlers_.dirty()) {
    auto action = std::move(after_save_);
    after_save_ = nullptr;
    action();
  }
}

void FileDialogs::draw(Preferences& prefs, float s, bool compare, const std::string& stem) {
  if (const auto chosen = browser_.draw()) {
    prefs.last_directory = browser_.directory().string();
    switch (purpose_) {
      case Purpose::Open:
        handlers_.open(*chosen);
        break;
      case Purpose::SaveAs:
        handlers_.save_as(*chosen);
        saved();
        break;
      case Purpose::Export:
        handlers_.export_file(*chosen);
        break;
      case Purpose::Screenshot:
        handlers_.screenshot(*chosen);
        break;
    }
  }

  if (screenshot_request_) {
    ImGui::OpenPopup("Screenshot");
    screenshot_request_ = false;
  }
  if (ImGui::BeginPopupModal("Screenshot", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextDisabled("Rendered offscreen; the interface is not included.");
    int size[2] = {prefs.screenshot_width, prefs.screenshot_height};
    if (ImGui::InputInt2("Size (px)", size)) {
      prefs.screenshot_width = std::clamp(size[0], 16, 8192);
      prefs.screenshot_height = std::clamp(size[1], 16, 8192);
    }
    ImGui::Checkbox("Transparent background", &prefs.screenshot_transparent);
    ImGui::Text(compare ? "Both panels of the comparison." : "The current view.");
    if (ImGui::Button("Choose file...", ImVec2(140 * s, 0))) {
      ImGui::CloseCurrentPopup();
      browse(Purpose::Screenshot, handlers_.start_dir(), stem + ".png");
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100 * s, 0))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }

  if (error_request_) {
    ImGui::OpenPopup("Problem###error");
    error_request_ = false;
  }
  if (ImGui::BeginPopupModal("Problem###error", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.5f, 1), "%s", error_title_.c_str());
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
    ImGui::TextUnformatted(error_message_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextDisabled("Nothing was changed.");
    // Keys count only after the first frame: the Enter that confirmed a file dialog is still
    // "pressed" in the frame this modal opens.
    const bool keys = !ImGui::IsWindowAppearing();
    if (ImGui::Button("OK", ImVec2(120 * s, 0)) ||
        (keys && (ImGui::IsKeyPressed(GLFW_KEY_ENTER) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))))
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }

  if (report_request_) {
    ImGui::OpenPopup("Report###report");
    report_request_ = false;
  }
  if (ImGui::BeginPopupModal("Report###report", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(report_title_.c_str());
    // As wide as its longest line when the window allows (else it scrolls), as tall as its
    // lines up to 60 % of the window.
    const ImVec2 text = ImGui::CalcTextSize(report_text_.c_str());
    const ImVec2 most = ImGui::GetMainViewport()->Size;
    const ImGuiStyle& st = ImGui::GetStyle();
    const ImVec2 size(std::min(text.x + 2 * st.WindowPadding.x + st.ScrollbarSize, most.x * 0.85f),
                      std::min(text.y + 2 * st.WindowPadding.y + st.ScrollbarSize, most.y * 0.6f));
    ImGui::BeginChild("##report", size, true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(report_text_.c_str());
    ImGui::EndChild();
    const bool keys = !ImGui::IsWindowAppearing();
    if (ImGui::Button("OK", ImVec2(120 * s, 0)) ||
        (keys && (ImGui::IsKeyPressed(GLFW_KEY_ENTER) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))))
      ImGui::CloseCurrentPopup();
    ImGui::SameLine();
    if (ImGui::Button("Copy", ImVec2(120 * s, 0))) ImGui::SetClipboardText(report_text_.c_str());
    ImGui::EndPopup();
  }

  if (recovery_request_) {
    ImGui::OpenPopup("Recover unsaved work###recover");
    recovery_request_ = false;
  }
  if (recovery_ && ImGui::BeginPopupModal("Recover unsaved work###recover", nullptr,
                                          ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("PatchLab stopped before these changes were saved:");
    ImGui::BulletText("%s",
                      recovery_->document.empty() ? "a new scene" : recovery_->document.c_str());
    ImGui::BulletText("last autosaved %s", recovery_->when.c_str());
    ImGui::TextDisabled("Recover opens them as unsaved changes; Discard deletes them.");
    const ImVec2 b(120 * s, 0);
    const bool keys = !ImGui::IsWindowAppearing();
    std::function<void()> run;
    bool closed = false;
    if (ImGui::Button("Recover", b) || (keys && ImGui::IsKeyPressed(GLFW_KEY_ENTER))) {
      run = recovery_->recover;
      closed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", b)) {
      run = recovery_->discard;
      closed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Later", b) || (keys && ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))) closed = true;
    if (closed) {
      ImGui::CloseCurrentPopup();
      recovery_.reset();
    }
    ImGui::EndPopup();
    if (run) run();
  }

  if (confirm_request_) {
    ImGui::OpenPopup("Unsaved changes###confirm");
    confirm_request_ = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes###confirm", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The scene has unsaved changes. Save them before you %s?", confirm_what_.c_str());
    const ImVec2 b(120 * s, 0);
    if (ImGui::Button("Save", b)) {
      ImGui::CloseCurrentPopup();
      if (handlers_.save()) {
        if (!handlers_.dirty() && confirm_action_) confirm_action_();
      } else {
        // Untitled: the action waits for the Save As to succeed.
        after_save_ = confirm_action_;
        browse_save_as();
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", b)) {
      ImGui::CloseCurrentPopup();
      if (confirm_action_) confirm_action_();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", b) ||
        (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)))
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

}  // namespace pl
