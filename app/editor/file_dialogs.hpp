// The editor's dialogs around files: the in-app browser (open, save as, export mesh,
// screenshot), the error message, the unsaved-changes question and the screenshot options.
// What a chosen file means is the editor's (the handlers); this part owns only the dialogs'
// state. ImGui code.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "app/editor/file_browser.hpp"
#include "app/editor/logic/preferences.hpp"

namespace pl {

class FileDialogs {
 public:
  enum class Purpose { Open, SaveAs, ExportMesh, Screenshot };
  struct Handlers {
    std::function<void(const std::filesystem::path&)> open, save_as, export_mesh, screenshot;
    // Saves to the document's file; returns false when it has none (then Save As is asked).
    std::function<bool()> save;
    std::function<bool()> dirty;
    std::function<std::filesystem::path()> start_dir;  // where the browser opens
  };

  explicit FileDialogs(Handlers handlers) : handlers_(std::move(handlers)) {}

  // Opens the browser for `purpose` in `dir`, with `name` typed in.
  void browse(Purpose purpose, const std::filesystem::path& dir, const std::string& name = "");
  void show_error(const std::string& title, const std::string& message);
  // Runs `action` now when there are no unsaved changes, else asks: Save (then the action, also
  // after a Save As), Discard (the action), or Cancel.
  void confirm_discard(const std::string& what, std::function<void()> action);
  void show_screenshot_options() { screenshot_request_ = true; }
  // A Save As finished: runs the action that waited for it, if the save succeeded.
  void saved();

  // Draws whatever is open. `compare`: the screenshot holds both panels.
  void draw(Preferences& prefs, float ui_scale, bool compare, const std::string& stem);
  const std::filesystem::path& browser_directory() const { return browser_.directory(); }

 private:
  Handlers handlers_;
  FileBrowser browser_;
  Purpose purpose_ = Purpose::Open;
  std::string error_title_, error_message_;
  bool error_request_ = false;
  std::string confirm_what_;
  std::function<void()> confirm_action_, after_save_;
  bool confirm_request_ = false;
  bool screenshot_request_ = false;
};

}  // namespace pl
