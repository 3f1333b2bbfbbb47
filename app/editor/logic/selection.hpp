// What the user has selected: editable points (network vertices, edge handles, explicit patch
// points), network edges, network faces and explicit patches, in the order they were picked.
// Tools, actions, panels and the drawing all read this one list. It holds indices into the
// document's scene, so it remembers the network's structure it was made for: after any change
// of the document follow() keeps the items whose indices still name the same objects and
// clears the selection when a change renumbered them (an undone split or delete); a command
// whose renumbering is known (a delete) remaps the items and adopts the new structure.
// GUI-free and unit-tested.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/document/point_ref.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

struct SelectionItem {
  enum class Kind : uint8_t { Point, Edge, Face, Patch, Curve };
  Kind kind = Kind::Point;
  PointRef point;  // Kind::Point
  int index = -1;  // edge, face, patch or free-curve index

  static SelectionItem of_point(const PointRef& p) { return {Kind::Point, p, -1}; }
  static SelectionItem edge(int e) { return {Kind::Edge, {}, e}; }
  static SelectionItem face(int f) { return {Kind::Face, {}, f}; }
  static SelectionItem patch(int p) { return {Kind::Patch, {}, p}; }
  static SelectionItem curve(int c) { return {Kind::Curve, {}, c}; }  // a free curve, whole
  bool operator==(const SelectionItem&) const = default;
};

bool item_exists(const Scene& scene, const SelectionItem& item);
// "vertex 3", "edge 5 handle 1", "patch 0 point 7", "edge 5", "face 1", "patch 0", "curve 2".
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

  // After the document changed. When every element of the network the selection was made for
  // keeps its index (moves, schemes, names, elements only appended, or only removed from the
  // end), items that no longer exist are dropped (Pruned when some were); otherwise indices may
  // name other objects now and the selection is cleared (Cleared, also when it was empty).
  enum class Followed { Kept, Pruned, Cleared };
  Followed follow(const Scene& scene);
  // The items were made to fit `scene` by the caller (after a command whose index changes it
  // knows): remembers its structure, drops what does not exist.
  void adopt(const Scene& scene);
  // After a deletion (indices as before it): removed vertices, edges and faces and the handles
  // of removed edges are dropped, the others renumbered. Call adopt() with the new scene next.
  void remap(const Removed& removed);
  // After free curves were deleted (`gone`: their indices before it, increasing): the deleted
  // curves and their points are dropped, the later curves renumbered.
  void remap_curves(const std::vector<int>& gone);

  std::vector<PointRef> points() const;                      // the selected points, in order
  std::vector<int> of_kind(SelectionItem::Kind kind) const;  // edge, face or patch indices
  bool has(SelectionItem::Kind kind) const;

  // Changes whenever the selection does (panels and overlays cache on it).
  uint64_t serial() const { return serial_; }
  // Changes whenever follow() or adopt() met a network of another structure (what was picked
  // under the cursor before may name another object now).
  uint64_t structure_serial() const { return structure_serial_; }

 private:
  void changed() { ++serial_; }
  std::vector<SelectionItem> items_;
  uint64_t serial_ = 0, structure_serial_ = 0;
  // The network's structure the indices refer to: vertex positions only when their count
  // changes (to tell an appended vertex from a renumbering), edge ends and face loops.
  struct Structure {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 2>> edges;
    std::vector<std::vector<int>> faces;
  };
  static Structure structure_of(const Scene& scene);
  Structure structure_;
};

// "face 1, vertex 3" (at most `limit` items, then "... (N items)").
std::string describe(const Selection& selection, std::size_t limit = 8);

}  // namespace pl
