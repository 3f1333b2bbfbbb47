#include "app/editor/logic/selection.hpp"

#include <algorithm>
#include <sstream>

#include "app/editor/logic/point_names.hpp"

namespace pl {

bool item_exists(const Scene& scene, const SelectionItem& item) {
  switch (item.kind) {
    case SelectionItem::Kind::Point:
      return point_exists(scene, item.point);
    case SelectionItem::Kind::Edge:
      return scene.network && item.index >= 0 && item.index < int(scene.network->edges.size());
    case SelectionItem::Kind::Face:
      return scene.network && item.index >= 0 && item.index < int(scene.network->faces.size());
    case SelectionItem::Kind::Patch:
      return item.index >= 0 && item.index < int(scene.patches.size());
  }
  return false;
}

std::string describe(const SelectionItem& item) {
  switch (item.kind) {
    case SelectionItem::Kind::Point:
      return describe(item.point);
    case SelectionItem::Kind::Edge:
      return "edge " + std::to_string(item.index);
    case SelectionItem::Kind::Face:
      return "face " + std::to_string(item.index);
    case SelectionItem::Kind::Patch:
      return "patch " + std::to_string(item.index);
  }
  return "?";
}

std::optional<SelectionItem> parse_item_name(const std::string& name) {
  if (const auto p = parse_point_name(name)) return SelectionItem::of_point(*p);
  std::istringstream in(name);
  std::string word, rest;
  int i = -1;
  if (!(in >> word >> i) || i < 0 || in >> rest) return std::nullopt;
  if (word == "edge") return SelectionItem::edge(i);
  if (word == "face") return SelectionItem::face(i);
  if (word == "patch") return SelectionItem::patch(i);
  return std::nullopt;
}

bool Selection::contains(const SelectionItem& item) const {
  return std::find(items_.begin(), items_.end(), item) != items_.end();
}

void Selection::clear() {
  if (items_.empty()) return;
  items_.clear();
  changed();
}

void Selection::set(std::vector<SelectionItem> items) {
  std::vector<SelectionItem> unique;
  for (const SelectionItem& i : items)
    if (std::find(unique.begin(), unique.end(), i) == unique.end()) unique.push_back(i);
  if (unique == items_) return;
  items_ = std::move(unique);
  changed();
}

void Selection::add(const SelectionItem& item) {
  if (contains(item)) return;
  items_.push_back(item);
  changed();
}

void Selection::remove(const SelectionItem& item) {
  const auto it = std::find(items_.begin(), items_.end(), item);
  if (it == items_.end()) return;
  items_.erase(it);
  changed();
}

void Selection::click(const SelectionItem& item, SelectMode mode) {
  switch (mode) {
    case SelectMode::Replace:
      if (!contains(item)) set({item});
      break;
    case SelectMode::Add:
      add(item);
      break;
    case SelectMode::Toggle:
      contains(item) ? remove(item) : add(item);
      break;
  }
}

bool Selection::prune(const Scene& scene) {
  const auto end = std::remove_if(items_.begin(), items_.end(),
                                  [&](const SelectionItem& i) { return !item_exists(scene, i); });
  if (end == items_.end()) return false;
  items_.erase(end, items_.end());
  changed();
  return true;
}

std::vector<PointRef> Selection::points() const {
  std::vector<PointRef> r;
  for (const SelectionItem& i : items_)
    if (i.kind == SelectionItem::Kind::Point) r.push_back(i.point);
  return r;
}

std::vector<int> Selection::of_kind(SelectionItem::Kind kind) const {
  std::vector<int> r;
  for (const SelectionItem& i : items_)
    if (i.kind == kind && kind != SelectionItem::Kind::Point) r.push_back(i.index);
  return r;
}

bool Selection::has(SelectionItem::Kind kind) const {
  return std::any_of(items_.begin(), items_.end(),
                     [&](const SelectionItem& i) { return i.kind == kind; });
}

std::string describe(const Selection& selection, std::size_t limit) {
  std::string s;
  const auto& items = selection.items();
  for (std::size_t i = 0; i < items.size() && i < limit; ++i)
    s += (i ? ", " : "") + describe(items[i]);
  if (items.size() > limit) s += ", ... (" + std::to_string(items.size()) + " items)";
  return s;
}

}  // namespace pl
