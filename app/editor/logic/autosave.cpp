#include "app/editor/logic/autosave.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/json_node.hpp"
#include "core/io/scene_io.hpp"

namespace pl {

namespace fs = std::filesystem;

namespace {

std::string stem(long pid) {
  return "autosave-" + std::to_string(pid);
}

bool running(long pid) {
  return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH);
}

}  // namespace

Autosave::Autosave(std::optional<fs::path> dir, std::chrono::milliseconds interval, long pid)
    : dir_(std::move(dir)), interval_(interval), pid_(pid > 0 ? pid : long(::getpid())) {}

std::optional<fs::path> Autosave::file() const {
  if (!dir_) return std::nullopt;
  return *dir_ / (stem(pid_) + ".json");
}

bool Autosave::tick(const Scene& scene, bool dirty, const std::string& document,
                    Clock::time_point now) {
  if (!dir_ || !dirty) return false;
  if (last_write_ && now - *last_write_ < interval_) return false;
  last_write_ = now;  // a failing disk is retried at the same pace, not every frame
  written_ = true;    // (even a failed write may have left a file to remove)
  try {
    std::error_code ec;
    fs::create_directories(*dir_, ec);
    // The scene first: an .info without its scene is never offered.
    write_file_atomically(*file(), scene_to_json(scene));
    write_file_atomically(*dir_ / (stem(pid_) + ".info"),
                          nlohmann::json{{"document", document}}.dump() + "\n");
    last_error_.clear();
    return true;
  } catch (const DataError& e) {
    last_error_ = e.what();
    return false;
  }
}

void Autosave::discard() {
  last_write_.reset();
  // Called every frame while the scene is clean: nothing to do unless this editor wrote.
  if (!dir_ || !written_) return;
  written_ = false;
  std::error_code ec;
  fs::remove(*dir_ / (stem(pid_) + ".json"), ec);
  fs::remove(*dir_ / (stem(pid_) + ".info"), ec);
}

std::vector<Autosave::Recovery> Autosave::pending() const {
  std::vector<Recovery> r;
  if (!dir_) return r;
  std::error_code ec;
  for (fs::directory_iterator it(*dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    long pid = 0;
    std::size_t used = 0;
    if (name.rfind("autosave-", 0) != 0 || it->path().extension() != ".json") continue;
    try {
      pid = std::stol(name.substr(9), &used);
    } catch (const std::exception&) {
      continue;
    }
    if (name.substr(9 + used) != ".json" || pid == pid_ || running(pid)) continue;
    Recovery rec;
    rec.file = it->path();
    rec.written = fs::last_write_time(rec.file, ec);
    try {
      const auto info = nlohmann::json::parse(read_text_file(*dir_ / (stem(pid) + ".info")));
      rec.document = info.value("document", "");
    } catch (const std::exception&) {
      // No (or a broken) .info: still the user's work; offered as a new scene.
    }
    r.push_back(std::move(rec));
  }
  std::sort(r.begin(), r.end(),
            [](const Recovery& a, const Recovery& b) { return a.written > b.written; });
  return r;
}

Scene Autosave::recover(const Recovery& r) {
  return read_scene(r.file);
}

void Autosave::drop(const Recovery& r) {
  std::error_code ec;
  fs::remove(r.file, ec);
  fs::path info = r.file;
  info.replace_extension(".info");
  fs::remove(info, ec);
}

}  // namespace pl
