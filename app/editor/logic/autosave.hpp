// Crash recovery for the editor, GUI-free. While the scene has unsaved changes the editor calls
// tick() every frame; at most every `interval` it writes the scene atomically to
// DIR/autosave-PID.json (DIR = $XDG_STATE_HOME/patchlab, never the working directory), with the
// document's path beside it in DIR/autosave-PID.info. A successful save (or a scene back at its
// saved state) calls discard(). At the next start, pending() lists the autosaves of editors
// that are no longer running (a crash, SIGKILL): the editor offers the newest back, then
// recover() reads it or drop() deletes it. Two editors running at once never see each other's.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

class Autosave {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kInterval{3000};

  // dir: where autosaves live (state_dir()); nullopt keeps none (no usable home directory).
  explicit Autosave(std::optional<std::filesystem::path> dir,
                    std::chrono::milliseconds interval = kInterval, long pid = 0 /* getpid() */);

  // Writes the scene if it is dirty and the last write is `interval` old (or there was none).
  // document: the file the scene was opened from or saved as ("" for a new scene). Returns
  // whether it wrote. A failed write (disk full) is not an error for the editor: the next tick
  // tries again; last_error() says why.
  bool tick(const Scene& scene, bool dirty, const std::string& document, Clock::time_point now);
  // The scene was saved (or is clean again): its autosave goes. Cheap when there is none, so
  // the editor calls it every frame the scene is clean.
  void discard();
  const std::string& last_error() const { return last_error_; }
  std::optional<std::filesystem::path> file() const;  // this editor's autosave

  struct Recovery {
    std::filesystem::path file;  // the autosaved scene
    std::string document;        // the file it was an edit of, "" for a new scene
    std::filesystem::file_time_type written;
  };
  // Autosaves left by editors that no longer run, newest first.
  std::vector<Recovery> pending() const;
  // The scene of a recovery (throws DataError if it cannot be read), and removing one.
  static Scene recover(const Recovery& r);
  static void drop(const Recovery& r);

 private:
  std::optional<std::filesystem::path> dir_;
  std::chrono::milliseconds interval_;
  long pid_;
  std::optional<Clock::time_point> last_write_;
  bool written_ = false;  // a file of this editor may exist
  std::string last_error_;
};

}  // namespace pl
