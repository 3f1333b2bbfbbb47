#include "app/document/document.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "app/document/scene_file.hpp"
#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl {

Document::Document(Scene scene, std::filesystem::path path)
    : scene_(std::move(scene)), path_(std::move(path)) {}

Document Document::open(const std::filesystem::path& path) {
  return Document(read_scene(path), path);
}

void Document::record(std::string label, Scene before, std::string merge_key) {
  history_.resize(history_position_);  // a new edit discards the redo branch
  if (saved_position_ > history_position_)
    saved_position_ = std::numeric_limits<std::size_t>::max();
  history_.push_back({std::move(label), std::move(before), scene_, std::move(merge_key), clock_()});
  ++history_position_;
}

std::string Document::execute(std::unique_ptr<Command> command) {
  if (drag_) end_drag();
  Scene next = scene_;
  command->apply(next);  // a refusal throws here: nothing has changed
  std::string label = command->label();
  std::string key = command->merge_key();
  const auto now = clock_();
  Step* last = history_position_ > 0 ? &history_[history_position_ - 1] : nullptr;
  const bool merge = may_merge_ && last && !key.empty() && key == last->merge_key &&
                     history_position_ == history_.size() && saved_position_ != history_position_ &&
                     (gesture_ || now - last->time <= kMergeWindow);
  Scene before = std::exchange(scene_, std::move(next));
  if (merge) {
    last->after = scene_;
    last->time = now;
  } else {
    record(label, std::move(before), std::move(key));
  }
  may_merge_ = true;
  changed();
  return label;
}

void Document::begin_gesture() {
  may_merge_ = false;
  gesture_ = true;
}

void Document::end_gesture() {
  may_merge_ = false;
  gesture_ = false;
}

bool Document::undo() {
  if (drag_) cancel_drag();
  may_merge_ = false;
  if (!can_undo()) return false;
  scene_ = history_[--history_position_].before;
  changed();
  return true;
}

bool Document::redo() {
  if (drag_) cancel_drag();
  may_merge_ = false;
  if (!can_redo()) return false;
  scene_ = history_[history_position_++].after;
  changed();
  return true;
}

std::string Document::undo_label() const {
  return can_undo() ? history_[history_position_ - 1].label : std::string();
}
std::string Document::redo_label() const {
  return can_redo() ? history_[history_position_].label : std::string();
}

void Document::begin_drag(std::vector<PointRef> points, HandleMode mode) {
  if (drag_) end_drag();
  for (const PointRef& p : points)
    if (!point_exists(scene_, p)) throw std::invalid_argument("no such point: " + describe(p));
  Drag d;
  d.points = std::move(points);
  d.mode = mode;
  for (const PointRef& p : d.points) d.start.push_back(point_position(scene_, p));
  d.current = d.start;
  const bool network_moves = std::any_of(d.points.begin(), d.points.end(), [](const PointRef& p) {
    return p.kind == PointRef::Kind::NetworkVertex || p.kind == PointRef::Kind::EdgeHandle;
  });
  for (const PointRef& p : d.points)
    d.free_defaults.push_back(p.kind == PointRef::Kind::FreePoint && !network_moves
                                  ? std::optional(free_point_default(scene_, p))
                                  : std::nullopt);
  if (scene_.network) {
    const Network& net = *scene_.network;
    std::vector<int> vertices, edges;
    for (const PointRef& p : d.points) {
      if (p.kind == PointRef::Kind::NetworkVertex) vertices.push_back(p.index);
      if (p.kind == PointRef::Kind::EdgeHandle) vertices.push_back(net.edges[p.object].v[p.index]);
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (int v : vertices) {
      d.vertices.emplace_back(v, net.vertices[v]);
      if (!net.normals.empty()) d.normals.emplace_back(v, net.normals[v]);
      for (int e : edges_at(net, v)) edges.push_back(e);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (int e : edges) d.handles.emplace_back(e, net.edges[e].handles);
  }
  d.before = scene_;
  drag_ = std::move(d);
  may_merge_ = false;
}

void Document::restore_drag_start() {
  if (!scene_.network) return;
  Network& net = *scene_.network;
  for (const auto& [v, p] : drag_->vertices) net.vertices[v] = p;
  for (const auto& [v, n] : drag_->normals) net.normals[v] = n;
  for (const auto& [e, h] : drag_->handles) net.edges[e].handles = h;
}

void Document::drag_to(const std::vector<Vec3>& positions) {
  if (!drag_ || positions.size() != drag_->points.size())
    throw std::invalid_argument("drag_to needs one position per dragged point");
  restore_drag_start();
  move_points(scene_, drag_->points, positions, drag_->mode, drag_->free_defaults);
  drag_->current = positions;
  // Free points alone, the network staying put: only their faces' offsets changed.
  std::optional<std::vector<int>> faces = std::vector<int>{};
  for (std::size_t i = 0; i < drag_->points.size() && faces; ++i) {
    if (drag_->points[i].kind == PointRef::Kind::FreePoint && drag_->free_defaults[i])
      faces->push_back(drag_->points[i].object);
    else
      faces.reset();
  }
  changed(std::move(faces));
}

void Document::changed(std::optional<std::vector<int>> interior_faces) {
  ++revision_;
  edits_[revision_ % kEditRecord] = std::move(interior_faces);
}

std::optional<std::vector<int>> Document::interior_faces_since(uint64_t since) const {
  if (since > revision_ || revision_ - since > kEditRecord) return std::nullopt;
  std::vector<int> faces;
  for (uint64_t r = since + 1; r <= revision_; ++r) {
    const auto& edit = edits_[r % kEditRecord];
    if (!edit) return std::nullopt;
    faces.insert(faces.end(), edit->begin(), edit->end());
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

void Document::end_drag() {
  if (!drag_) return;
  Drag d = std::move(*drag_);
  drag_.reset();
  may_merge_ = false;
  if (d.current == d.start) return;  // a click without motion is no edit
  // The scene already holds the end state: record it as one step.
  record(MovePointsCommand(d.points, d.current, d.mode).label(), std::move(d.before));
}

void Document::cancel_drag() {
  if (!drag_) return;
  scene_ = std::move(drag_->before);
  drag_.reset();
  may_merge_ = false;
  changed();
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
  save_scene_file(path, scene_);
  path_ = path;
  saved_position_ = history_position_;
  may_merge_ = false;
}

}  // namespace pl
