// The open scene with its file, undo history and unsaved-changes state.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

class Document {
 public:
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

  void execute(std::unique_ptr<Command> command);
  bool can_undo() const { return history_position_ > 0; }
  bool can_redo() const { return history_position_ < history_.size(); }
  bool undo();
  bool redo();
  std::string undo_label() const;
  std::string redo_label() const;

  // A drag moves points live; end_drag() records the whole drag as one undo step, cancel_drag()
  // puts the points back. Points that do not exist are rejected (std::invalid_argument).
  void begin_drag(std::vector<PointRef> points);
  void drag_to(const std::vector<Vec3>& positions);
  void end_drag();
  void cancel_drag();
  bool dragging() const { return drag_.has_value(); }
  const std::vector<PointRef>& drag_points() const;

  // Atomic; throws DataError and keeps the previous file on failure.
  void save();
  void save_as(const std::filesystem::path& path);

 private:
  struct Drag {
    std::vector<PointRef> points;
    std::vector<Vec3> start, current;
    Scene before;
  };
  struct Step {
    std::string label;
    Scene before, after;
  };
  void record(std::string label, Scene before);

  Scene scene_;
  std::filesystem::path path_;
  std::vector<Step> history_;
  std::size_t history_position_ = 0;  // commands [0, position) are applied
  std::size_t saved_position_ = 0;    // history position at the last save (SIZE_MAX: never)
  uint64_t revision_ = 0;
  std::optional<Drag> drag_;
};

}  // namespace pl
