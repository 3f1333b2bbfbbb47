#include "app/document/document.hpp"

#include <limits>
#include <stdexcept>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl {

Document::Document(Scene scene, std::filesystem::path path)
    : scene_(std::move(scene)), path_(std::move(path)) {}

Document Document::open(const std::filesystem::path& path) {
  return Document(read_scene(path), path);
}

void Document::record(std::string label, Scene before) {
  history_.resize(history_position_);  // a new edit discards the redo branch
  if (saved_position_ > history_position_)
    saved_position_ = std::numeric_limits<std::size_t>::max();
  history_.push_back({std::move(label), std::move(before), scene_});
  ++history_position_;
}

void Document::execute(std::unique_ptr<Command> command) {
  if (drag_) end_drag();
  Scene before = scene_;
  command->apply(scene_);
  record(command->label(), std::move(before));
  ++revision_;
}

bool Document::undo() {
  if (drag_) cancel_drag();
  if (!can_undo()) return false;
  scene_ = history_[--history_position_].before;
  ++revision_;
  return true;
}

bool Document::redo() {
  if (drag_) cancel_drag();
  if (!can_redo()) return false;
  scene_ = history_[history_position_++].after;
  ++revision_;
  return true;
}

std::string Document::undo_label() const {
  return can_undo() ? history_[history_position_ - 1].label : std::string();
}
std::string Document::redo_label() const {
  return can_redo() ? history_[history_position_].label : std::string();
}

void Document::begin_drag(std::vector<PointRef> points) {
  if (drag_) end_drag();
  for (const PointRef& p : points)
    if (!point_exists(scene_, p)) throw std::invalid_argument("no such point: " + describe(p));
  Drag d;
  d.points = std::move(points);
  for (const PointRef& p : d.points) d.start.push_back(point_position(scene_, p));
  d.current = d.start;
  d.before = scene_;
  drag_ = std::move(d);
}

void Document::drag_to(const std::vector<Vec3>& positions) {
  if (!drag_ || positions.size() != drag_->points.size())
    throw std::invalid_argument("drag_to needs one position per dragged point");
  MovePointsCommand(drag_->points, positions).apply(scene_);
  drag_->current = positions;
  ++revision_;
}

void Document::end_drag() {
  if (!drag_) return;
  Drag d = std::move(*drag_);
  drag_.reset();
  if (d.current == d.start) return;  // a click without motion is no edit
  // The scene already holds the end state: record it as one step.
  record(MovePointsCommand(d.points, d.current).label(), std::move(d.before));
}

void Document::cancel_drag() {
  if (!drag_) return;
  scene_ = std::move(drag_->before);
  drag_.reset();
  ++revision_;
}

const std::vector<PointRef>& Document::drag_points() const {
  static const std::vector<PointRef> none;
  return drag_ ? drag_->points : none;
}

void Document::save() {
  if (path_.empty()) throw DataError("", "", "the scene has no file name yet: use Save As");
  save_as(path_);
}

void Document::save_as(const std::filesystem::path& path) {
  if (drag_) end_drag();
  write_scene(path, scene_);
  path_ = path;
  saved_position_ = history_position_;
}

}  // namespace pl
