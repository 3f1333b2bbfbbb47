// What the user has selected: editable points (network vertices, edge handles, explicit patch
// points), network edges, network faces and explicit patches, in the order they were picked.
// Tools, actions, panels and the drawing all read this one list; it holds indices into the
// document's scene, so after an edit that may remove objects (undo, a topology command, a new
// document) prune() drops what no longer exists. GUI-free and unit-tested.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/document/point_ref.hpp"

namespace pl {

struct SelectionItem {
  enum class Kind : uint8_t { Point, Edge, Face, Patch };
  Kind kind = Kind::Point;
  PointRef point;  // Kind::Point
  int index = -1;  // edge, face or patch index

  static SelectionItem of_point(const PointRef& p) { return {Kind::Point, p, -1}; }
  static SelectionItem edge(int e) { return {Kind::Edge, {}, e}; }
  static SelectionItem face(int f) { return {Kind::Face, {}, f}; }
  static SelectionItem patch(int p) { return {Kind::Patch, {}, p}; }
  bool operator==(const SelectionItem&) const = default;
};

bool item_exists(const Scene& scene, const SelectionItem& item);
// "vertex 3", "edge 5 handle 1", "patch 0 point 7", "edge 5", "face 1", "patch 0".
std::string describe(const SelectionItem& item);
// The inverse of describe(); nullopt for anything else.
std::optional<SelectionItem> parse_item_name(const std::string& name);

// How a click changes the selection (the CAD convention): replace, Shift adds, Ctrl toggles.
enum class SelectMode { Replace, Add, Toggle };

class Selection {
 public:
  const std::vector<SelectionItem>& items() const { return items_; }
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  bool contains(const SelectionItem& item) const;

  void clear();
  void set(std::vector<SelectionItem> items);  // duplicates dropped, order kept
  void add(const SelectionItem& item);
  void remove(const SelectionItem& item);
  // A click on `item`. Replace on an item already selected keeps the selection, so that pressing
  // on one of several selected points drags them all.
  void click(const SelectionItem& item, SelectMode mode);
  // Drops items the scene no longer has. Returns true if something was dropped.
  bool prune(const Scene& scene);

  std::vector<PointRef> points() const;                      // the selected points, in order
  std::vector<int> of_kind(SelectionItem::Kind kind) const;  // edge, face or patch indices
  bool has(SelectionItem::Kind kind) const;

  // Changes whenever the selection does (panels and overlays cache on it).
  uint64_t serial() const { return serial_; }

 private:
  void changed() { ++serial_; }
  std::vector<SelectionItem> items_;
  uint64_t serial_ = 0;
};

// "face 1, vertex 3" (at most `limit` items, then "... (N items)").
std::string describe(const Selection& selection, std::size_t limit = 8);

}  // namespace pl
