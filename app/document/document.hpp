// The open scene with its file, undo history and unsaved-changes state.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

class Document {
 public:
  using Clock = std::chrono::steady_clock;

  // A document without a path is untitled: save() refuses, save_as() names it.
  explicit Document(Scene scene = {}, std::filesystem::path path = {});
  // Throws DataError; nothing changes on failure.
  static Document open(const std::filesystem::path& path);

  const Scene& scene() const { return scene_; }
  const std::filesystem::path& path() const { return path_; }
  bool dirty() const {
    return history_position_ != saved_position_ || (drag_ && drag_->current != drag_->start);
  }
  // Increases with every change of the scene (edits, undo, redo, drag steps).
  uint64_t revision() const { return revision_; }
  // The network faces whose GB interior offsets alone changed from revision `since` to now (the
  // steps of a free-point drag), so that an evaluation can follow them without comparing the
  // whole scene (SceneEvaluation::sync's InteriorEdit); empty if nothing changed. None when
  // anything else changed in between, or `since` is older than the last kEditRecord revisions.
  std::optional<std::vector<int>> interior_faces_since(uint64_t since) const;
  static constexpr std::size_t kEditRecord = 64;

  // Applies the command to a copy of the scene and makes that the scene, as one undo step;
  // returns the command's label (what the status bar shows). If the command throws (EditRefused
  // for a refused request) the document is unchanged and the exception propagates. A command
  // with a merge key equal to the previous step's, executed within kMergeWindow of it with
  // nothing in between (no undo, redo, drag or save), extends that step instead: one undo step
  // for a run of arrow-key nudges.
  std::string execute(std::unique_ptr<Command> command);
  static constexpr std::chrono::milliseconds kMergeWindow{1500};

  // A gesture made of commands (a dragged normal: one command per mouse move) is one undo step
  // however long the designer pauses: begin_gesture() ends any run of merged commands before it,
  // and until end_gesture() a command with the previous step's merge key extends that step
  // without the time limit. Undo, redo, a drag or a save in between still start a new step.
  void begin_gesture();
  void end_gesture();
  bool in_gesture() const { return gesture_; }

  bool can_undo() const { return history_position_ > 0; }
  bool can_redo() const { return history_position_ < history_.size(); }
  bool undo();
  bool redo();
  std::string undo_label() const;
  std::string redo_label() const;

  // A drag moves points live; end_drag() records the whole drag as one undo step, cancel_drag()
  // puts the points back. Handles move as `mode` says (kept in their vertex's tangent plane by
  // default); each step starts again from the drag's start, so a turned plane does not drift.
  // Points that do not exist are rejected (std::invalid_argument).
  void begin_drag(std::vector<PointRef> points, HandleMode mode = HandleMode::KeepPlane);
  void drag_to(const std::vector<Vec3>& positions);
  void end_drag();
  void cancel_drag();
  bool dragging() const { return drag_.has_value(); }
  const std::vector<PointRef>& drag_points() const;

  // Atomic, as the extension says (scene_file.hpp: .json, or .gbp for a single GB patch);
  // throws DataError and keeps the previous file (and the document's path) on failure.
  void save();
  void save_as(const std::filesystem::path& path);

  // The time source of merging (tests).
  void set_clock(std::function<Clock::time_point()> clock) { clock_ = std::move(clock); }

 private:
  struct Drag {
    std::vector<PointRef> points;
    HandleMode mode = HandleMode::KeepPlane;
    std::vector<Vec3> start, current;
    // What a step may change at the dragged vertices and at the vertices of dragged handles:
    // their positions, normals and the handles of their edges, as they were at the start.
    std::vector<std::pair<int, Vec3>> vertices;
    std::vector<std::pair<int, std::optional<Vec3>>> normals;
    std::vector<std::pair<int, std::array<Vec3, 2>>> handles;
    // Per dragged point: a free point's default position when the drag moves no network point
    // (it stays put, so a frame only writes offsets), else nullopt.
    std::vector<std::optional<Vec3>> free_defaults;
    Scene before;
  };
  struct Step {
    std::string label;
    Scene before, after;
    std::string merge_key;  // empty: never extended
    Clock::time_point time;
  };
  void record(std::string label, Scene before, std::string merge_key = {});
  // Counts a change of the scene: the faces whose offsets alone it changed, or none for any
  // other change.
  void changed(std::optional<std::vector<int>> interior_faces = std::nullopt);
  void restore_drag_start();

  Scene scene_;
  std::filesystem::path path_;
  std::vector<Step> history_;
  std::size_t history_position_ = 0;  // commands [0, position) are applied
  std::size_t saved_position_ = 0;    // history position at the last save (SIZE_MAX: never)
  uint64_t revision_ = 0;
  // What each of the last revisions changed (revision r at edits_[r % kEditRecord]).
  std::vector<std::optional<std::vector<int>>> edits_ =
      std::vector<std::optional<std::vector<int>>>(kEditRecord);
  std::optional<Drag> drag_;
  bool may_merge_ = false;  // the last change was a step recorded by execute()
  bool gesture_ = false;    // between begin_gesture() and end_gesture()
  std::function<Clock::time_point()> clock_ = [] { return Clock::now(); };
};

}  // namespace pl
