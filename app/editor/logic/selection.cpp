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
    case SelectionItem::Kind::Curve:
      return item.index >= 0 && item.index < int(scene.curves.size());
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
    case SelectionItem::Kind::Curve:
      return "curve " + std::to_string(item.index);
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
  if (word == "curve") return SelectionItem::curve(i);
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

namespace {

// Whether the shorter of a and b is the start of the longer: every element they share keeps its
// index.
template <class T>
bool one_extends_the_other(const std::vector<T>& a, const std::vector<T>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  return std::equal(a.begin(), a.begin() + n, b.begin());
}

// The new index of `i` after removing the sorted indices `gone`, or -1 when i is one of them.
int renumbered(int i, const std::vector<int>& gone) {
  const auto at = std::lower_bound(gone.begin(), gone.end(), i);
  if (at != gone.end() && *at == i) return -1;
  return i - int(at - gone.begin());
}

}  // namespace

Selection::Structure Selection::structure_of(const Scene& scene) {
  Structure s;
  if (!scene.network) return s;
  const Network& net = *scene.network;
  s.vertices = net.vertices;
  for (const NetworkEdge& e : net.edges) s.edges.push_back(e.v);
  for (const NetworkFace& f : net.faces) s.faces.push_back(f.loop);
  return s;
}

Selection::Followed Selection::follow(const Scene& scene) {
  static const Network kNone;
  const Network& net = scene.network ? *scene.network : kNone;
  Structure& was = structure_;
  // The common case (a move, a drag frame): the same structure, compared in place.
  bool same = was.vertices.size() == net.vertices.size() && was.edges.size() == net.edges.size() &&
              was.faces.size() == net.faces.size();
  for (std::size_t e = 0; same && e < net.edges.size(); ++e) same = net.edges[e].v == was.edges[e];
  for (std::size_t f = 0; same && f < net.faces.size(); ++f)
    same = net.faces[f].loop == was.faces[f];
  if (same) {
    was.vertices = net.vertices;  // moved vertices: what a later count change is compared with
    return prune(scene) ? Followed::Pruned : Followed::Kept;
  }
  Structure now = structure_of(scene);
  ++structure_serial_;
  const bool compatible = one_extends_the_other(was.vertices, now.vertices) &&
                          one_extends_the_other(was.edges, now.edges) &&
                          one_extends_the_other(was.faces, now.faces);
  structure_ = std::move(now);
  if (compatible) return prune(scene) ? Followed::Pruned : Followed::Kept;
  if (!items_.empty()) {
    items_.clear();
    changed();
  }
  return Followed::Cleared;
}

void Selection::adopt(const Scene& scene) {
  structure_ = structure_of(scene);
  ++structure_serial_;
  prune(scene);
}

void Selection::remap(const Removed& removed) {
  std::vector<SelectionItem> kept;
  for (SelectionItem i : items_) {
    int* index = nullptr;
    const std::vector<int>* gone = nullptr;
    if (i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::NetworkVertex) {
      index = &i.point.index;
      gone = &removed.vertices;
    } else if (i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::EdgeHandle) {
      index = &i.point.object;
      gone = &removed.edges;
    } else if (i.kind == SelectionItem::Kind::Edge) {
      index = &i.index;
      gone = &removed.edges;
    } else if (i.kind == SelectionItem::Kind::Face) {
      index = &i.index;
      gone = &removed.faces;
    }
    if (index) {
      *index = renumbered(*index, *gone);
      if (*index < 0) continue;
    }
    kept.push_back(i);
  }
  if (kept != items_) {
    items_ = std::move(kept);
    changed();
  }
}

void Selection::remap_curves(const std::vector<int>& gone) {
  std::vector<SelectionItem> kept;
  for (SelectionItem i : items_) {
    int* index =
        i.kind == SelectionItem::Kind::Curve ? &i.index
        : i.kind == SelectionItem::Kind::Point && i.point.kind == PointRef::Kind::CurvePoint
            ? &i.point.object
            : nullptr;
    if (index) {
      *index = renumbered(*index, gone);
      if (*index < 0) continue;
    }
    kept.push_back(i);
  }
  if (kept != items_) {
    items_ = std::move(kept);
    changed();
  }
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
