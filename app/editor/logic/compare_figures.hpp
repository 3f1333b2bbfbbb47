// The comparison's table of quality figures (core/analysis/scheme_comparison.hpp), computed off
// the hot path: on a worker thread, on a copy of the scene, only when asked for a new key (the
// editor asks once the views have settled after an edit, never during a drag). A request for a
// new key cancels the running one between two fillings. GUI-free and unit-tested.
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/scheme_comparison.hpp"

namespace pl {

struct FiguresKey {
  uint64_t revision = UINT64_MAX;  // the document's
  std::vector<int> faces;
  std::vector<FaceScheme> schemes;
  FaceScheme base = FaceScheme::GB;
  int density = 0;
  bool operator==(const FiguresKey&) const = default;
};

class CompareFigures {
 public:
  CompareFigures() = default;
  ~CompareFigures();  // cancels and waits for a running worker
  CompareFigures(const CompareFigures&) = delete;
  CompareFigures& operator=(const CompareFigures&) = delete;

  // Starts computing the figures for `key` on a copy of `scene` unless they are computed or
  // being computed for it already. Returns true when it started.
  bool request(const Scene& scene, const FiguresKey& key);
  // Takes a finished worker's result; returns true when it did.
  bool poll();
  // Stops a running computation (a drag began: the cores are the drag's); the next request
  // starts it again.
  void cancel();
  bool busy() const { return job_ != nullptr; }

  // The last figures computed (for result_key()), or none yet.
  const std::optional<SchemeComparison>& result() const { return result_; }
  const FiguresKey& result_key() const { return result_key_; }
  // Why the last computation failed ("" when it did not).
  const std::string& error() const { return error_; }
  // Throughput is timed for this long per face and scheme (the table's Msamples/s).
  double timing_ms = 5;

 private:
  struct Job {
    FiguresKey key;
    std::atomic<bool> cancel{false};
    std::optional<SchemeComparison> result;
    std::string error;
  };
  std::shared_ptr<Job> job_;
  std::future<void> worker_;
  std::vector<std::future<void>> cancelled_;  // still finishing their current filling
  std::optional<SchemeComparison> result_;
  FiguresKey result_key_;
  std::string error_;
};

// The faces the table shows: the selected faces, else the face with the most sides (the first
// of them), else none.
std::vector<int> figures_faces(const Network& network, const std::vector<int>& selected_faces);

}  // namespace pl
