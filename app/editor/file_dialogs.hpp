// The editor's dialogs around files: the in-app browser (open, save as, export a mesh or a CAD
// file, screenshot), the error message, a report (what a CAD export wrote), the unsaved-changes
// question, the crash-recovery offer and the screenshot options.
// What a chosen file means is the editor's (the handlers); this part owns only the dialogs'
// state. ImGui code.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "app/editor/file_browser.hpp"
#include "app/editor/logic/editor_shell.hpp"
#include "app/editor/logic/export_formats.hpp"
#include "app/editor/logic/preferences.hpp"

namespace pl {

class FileDialogs {
 public:
  enum class Purpose { Open, SaveAs, Export, Screenshot };
  struct Handlers {
    // export_file: a mesh (.obj .ply .off .stl) or CAD file (.step .stp .igs .iges).
    std::function<void(const std::filesystem::path&)> open, save_as, export_file, screenshot;
    // Saves to the document's file; returns false when it cannot (untitled, or its type cannot
    // hold the scene): then Save As is asked.
    std::function<bool()> save;
    std::function<bool()> dirty;
    std::function<std::filesystem::path()> start_dir;  // where the browser opens
    // Where Save As opens and the name typed in.
    std::function<std::pair<std::filesystem::path, std::string>()> save_as_start;
  };

  explicit FileDialogs(Handlers handlers) : handlers_(std::move(handlers)) {}

  // Opens the browser for `purpose` in `dir`, with `name` typed in.
  void browse(Purpose purpose, const std::filesystem::path& dir, const std::string& name = "");
  void browse_save_as();  // at save_as_start()
  // The export browser for `format` (File > Export As: its extensions listed and given to a
  // name typed without one), or for every export format (null: File > Export...).
  void browse_export(const std::filesystem::path& dir, const std::string& stem,
                     const ExportFormat* format);
  void show_error(const std::string& title, const std::string& message);
  // A message to read (and copy) in a scrolling box: what an export wrote.
  void show_report(const std::string& title, const std::string& text);
  // At start: the editor's autosave of unsaved work from `when` (an edit of `document`, or of a
  // new scene when empty) was left by a crash. Recover loads it, Discard deletes it; Later keeps
  // it for the next start.
  using RecoveryOffer = pl::RecoveryOffer;
  void offer_recovery(RecoveryOffer offer);
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
  std::string report_title_, report_text_;
  bool report_request_ = false;
  std::optional<RecoveryOffer> recovery_;
  bool recovery_request_ = false;
  std::string confirm_what_;
  std::function<void()> confirm_action_, after_save_;
  bool confirm_request_ = false;
  bool screenshot_request_ = false;
};

}  // namespace pl
