// File > Export to STEP or IGES without freezing the editor: export_cad runs on a worker thread
// on a copy of the scene (patches are shared and copied on write, so the copy is cheap and the
// document may change meanwhile), and the editor polls for the result once a frame. One export
// at a time. GUI-free and unit-tested.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string>

#include "core/cad/cad_export.hpp"

namespace pl {

class CadExportJob {
 public:
  using Clock = std::chrono::steady_clock;

  struct Result {
    std::filesystem::path target;
    bool ok = false;
    std::string text;  // cad_report_text on success, the error message otherwise
  };

  CadExportJob() = default;
  CadExportJob(const CadExportJob&) = delete;
  CadExportJob& operator=(const CadExportJob&) = delete;
  ~CadExportJob();  // waits for a running export (its file is written atomically either way)

  // Starts exporting `scene` to `target`; `finished` runs on the worker thread when it is done
  // (the editor wakes its event loop with it). Returns false, starting nothing, while an export
  // is running.
  bool start(Scene scene, std::filesystem::path target, CadExportOptions options,
             std::function<void()> finished = {});
  bool running() const { return future_.valid(); }
  const std::filesystem::path& target() const { return target_; }
  double seconds(Clock::time_point now = Clock::now()) const;

  // The result, once, when the export has finished; nullopt while it runs (or when idle).
  std::optional<Result> poll();

 private:
  std::future<Result> future_;
  std::filesystem::path target_;
  Clock::time_point started_{};
};

}  // namespace pl
