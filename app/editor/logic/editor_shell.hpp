// What only the editor's window can do, asked for by the editor model: the dialogs (a question
// about unsaved changes, a file to open, save or export to, an error, a report, the crash
// recovery offer, a new name) and waking the window when a worker has finished. The window
// answers by calling the model back (EditorModel::open_file, save_as, rename, ...); a test
// answers the same way, or records the question.
#pragma once

#include <functional>
#include <string>

#include "app/editor/logic/selection.hpp"

namespace pl {

// An autosave of unsaved work from `when` (an edit of `document`, or of a new scene when empty)
// that a crash left. Recover loads it, Discard deletes it; neither keeps it for the next start.
struct RecoveryOffer {
  std::string document, when;
  std::function<void()> recover, discard;
};

class EditorShell {
 public:
  virtual ~EditorShell() = default;
  // Runs `then` now when there are no unsaved changes, else once the user agreed (after saving
  // or discarding them); `doing` says what waits ("quit", "open another file").
  virtual void confirm_discard(const std::string& doing, std::function<void()> then) = 0;
  virtual void ask_open() = 0;     // a file to open: EditorModel::open_file
  virtual void ask_save_as() = 0;  // a name to save as: EditorModel::save_as
  virtual void ask_export() = 0;   // a file to export to: EditorModel::export_file
  virtual void ask_screenshot() = 0;
  // A new name for `item`, starting from `current`: EditorModel::rename.
  virtual void ask_name(const SelectionItem& item, const std::string& current) = 0;
  virtual void show_error(const std::string& title, const std::string& message) = 0;
  virtual void show_report(const std::string& title, const std::string& text) = 0;
  virtual void offer_recovery(RecoveryOffer offer) = 0;
  // A worker finished (a CAD export): draw a frame soon. Any thread.
  virtual void wake() = 0;
};

}  // namespace pl
