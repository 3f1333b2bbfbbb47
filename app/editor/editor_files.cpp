// Files: open (scene or .gbp import), save, save as, mesh export, screenshots, drag and drop,
// and the modals (errors, unsaved-changes questions, screenshot options).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>
#include <iostream>

#include "app/cli/load_input.hpp"
#include "app/editor/editor.hpp"
#include "app/editor/screenshot.hpp"
#include "core/io/atomic_file.hpp"
#include "core/base/data_error.hpp"
#include "core/mesh/mesh_export.hpp"

namespace pl {

namespace fs = std::filesystem;

fs::path Editor::browse_start_dir() const {
  std::error_code ec;
  if (!doc_.path().empty() && fs::is_directory(doc_.path().parent_path(), ec))
    return doc_.path().parent_path();
  if (!prefs_.last_directory.empty() && fs::is_directory(prefs_.last_directory, ec))
    return prefs_.last_directory;
  if (const char* home = std::getenv("HOME")) return home;
  return fs::current_path(ec);
}

void Editor::open_file(const fs::path& path) {
  try {
    // Scenes keep their path (Save writes them back); a .gbp is imported as a new scene, so
    // Save asks for a .json name instead of overwriting the GB file with JSON.
    Scene scene = load_input(path);
    const bool is_scene = path.extension() == ".json" || path.extension() == ".JSON";
    set_document(Document(std::move(scene), is_scene ? path : fs::path()));
    prefs_.last_directory = fs::absolute(path).parent_path().string();
    status_message_ = (is_scene ? "opened " : "imported ") + path.filename().string();
    status_time_ = Clock::now();
  } catch (const DataError& e) {
    show_error("Cannot open file", e.what());
  } catch (const std::exception& e) {
    show_error("Cannot open file", path.string() + ": " + e.what());
  }
}

void Editor::save() {
  try {
    doc_.save();
    status_message_ = "saved " + doc_.path().filename().string();
    status_time_ = Clock::now();
    if (options_.debug_point) {
      std::cout << "saved " << doc_.path().string() << " revision " << doc_.revision() << std::endl;
    }
  } catch (const DataError& e) {
    show_error("Cannot save", e.what());
  } catch (const std::exception& e) {
    show_error("Cannot save", e.what());
  }
}

void Editor::save_as(const fs::path& path) {
  try {
    doc_.save_as(path);
    prefs_.last_directory = path.parent_path().string();
    status_message_ = "saved " + path.filename().string();
    status_time_ = Clock::now();
  } catch (const DataError& e) {
    show_error("Cannot save", e.what());
  } catch (const std::exception& e) {
    show_error("Cannot save", path.string() + ": " + e.what());
  }
}

void Editor::export_mesh(const fs::path& path) {
  if (!main_view_) return;
  try {
    export_meshes(main_view_->fine().draw().surfaces, path);
    status_message_ = "exported " + path.filename().string();
    status_time_ = Clock::now();
  } catch (const DataError& e) {
    show_error("Cannot export", e.what());
  } catch (const std::exception& e) {
    show_error("Cannot export", path.string() + ": " + e.what());
  }
}

void Editor::take_screenshot(const fs::path& path) {
  if (!main_view_) return;
  try {
    ShotRequest r;
    r.width = prefs_.screenshot_width;
    r.height = prefs_.screenshot_height;
    r.transparent = prefs_.screenshot_transparent;
    const int panels = compare_ ? 2 : 1;
    const ColorRange range = current_range();
    for (int i = 0; i < panels; ++i) {
      ShotPanel p{&panel_view(i).gpu(), prefs_.display, range, ""};
      if (compare_) p.label = i == 0 ? "Gregory" : "Generalized Bezier";
      if (compare_ && difference_ && i == 1 && difference_gpu_) {
        const double m = difference_max_ > 0 ? difference_max_ : 1e-12;
        p.scene = difference_gpu_.get();
        p.settings.base = BaseMode::Curvature;
        p.settings.curvature = CurvatureKind::Mean;
        p.range = {-m, m};
        p.label = "GB: distance to Gregory";
        r.legend_title = "distance";
        r.legend_range = p.range;
      }
      r.panels.push_back(p);
    }
    if (r.legend_title.empty() && prefs_.display.base == BaseMode::Curvature) {
      r.legend_title = std::string(curvature_name(prefs_.display.curvature)) + " curvature";
      r.legend_range = range;
    }
    // The window's view, refitted only in aspect: same direction, target and zoom.
    r.camera = camera_;
    const Image image = render_screenshot(renderer_, r);
    write_file_atomically(path, encode_png(image));
    status_message_ = "wrote " + path.filename().string();
    status_time_ = Clock::now();
  } catch (const std::exception& e) {
    show_error("Cannot write the screenshot", path.string() + ": " + e.what());
  }
}

void Editor::handle_drops() {
  if (dropped_.empty()) return;
  const fs::path path = dropped_.front();
  dropped_.clear();  // one document at a time: the first dropped file
  confirm_discard("open " + path.filename().string(), [this, path] { open_file(path); });
}

void Editor::draw_file_dialogs() {
  if (const auto chosen = browser_.draw()) {
    prefs_.last_directory = browser_.directory().string();
    switch (browse_for_) {
      case BrowseFor::Open:
        open_file(*chosen);
        break;
      case BrowseFor::SaveAs:
        save_as(*chosen);
        break;
      case BrowseFor::ExportMesh:
        export_mesh(*chosen);
        break;
      case BrowseFor::Screenshot:
        take_screenshot(*chosen);
        break;
    }
  }
  if (show_screenshot_) {
    ImGui::OpenPopup("Screenshot");
    show_screenshot_ = false;
  }
  if (ImGui::BeginPopupModal("Screenshot", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextDisabled("Rendered offscreen; the interface is not included.");
    int size[2] = {prefs_.screenshot_width, prefs_.screenshot_height};
    if (ImGui::InputInt2("Size (px)", size)) {
      prefs_.screenshot_width = std::clamp(size[0], 16, 8192);
      prefs_.screenshot_height = std::clamp(size[1], 16, 8192);
    }
    ImGui::Checkbox("Transparent background", &prefs_.screenshot_transparent);
    ImGui::Text(compare_ ? "Both panels of the comparison." : "The current view.");
    if (ImGui::Button("Choose file...", ImVec2(140 * ui_scale_, 0))) {
      ImGui::CloseCurrentPopup();
      browse_for_ = BrowseFor::Screenshot;
      browser_.open("Save screenshot", "Save", browse_start_dir(), {".png"}, ".png",
                    doc_.path().stem().string() + ".png");
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100 * ui_scale_, 0))) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

void Editor::draw_modals() {
  if (error_pending_) {
    ImGui::OpenPopup("Problem###error");
    error_pending_ = false;
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
    if (ImGui::Button("OK", ImVec2(120 * ui_scale_, 0)) ||
        (keys && (ImGui::IsKeyPressed(GLFW_KEY_ENTER) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))))
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (confirm_pending_) {
    ImGui::OpenPopup("Unsaved changes###confirm");
    confirm_pending_ = false;
  }
  if (ImGui::BeginPopupModal("Unsaved changes###confirm", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The scene has unsaved changes. Save them before you %s?", confirm_what_.c_str());
    const ImVec2 b(120 * ui_scale_, 0);
    if (ImGui::Button("Save", b)) {
      ImGui::CloseCurrentPopup();
      if (doc_.path().empty()) {
        browse_for_ = BrowseFor::SaveAs;
        browser_.open("Save scene as", "Save", browse_start_dir(), {".json"}, ".json");
      } else {
        save();
        if (!doc_.dirty() && confirm_action_) confirm_action_();
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
