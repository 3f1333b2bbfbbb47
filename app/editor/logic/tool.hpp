// The active tool: what a left press in the view does. The select tool picks and drags; the
// authoring tools (add a vertex on the work plane, add an edge, make a face, ...) are further
// Tool classes, added to the ToolBox with one line and given an action (menu entry and key).
// A tool sees the mouse as PointerEvents, what lies under the cursor (the picker's result) and
// acts on the document through commands, so every tool is GUI-free and unit-tested.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/document/document.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/work_plane.hpp"

namespace pl {

// What a tool may act on.
struct ToolContext {
  Document& doc;
  Selection& selection;
  const Camera& camera;
  const WorkPlane& work_plane;
  // A line for the status bar ("split edge 3: face 1 is now a pentagon").
  std::function<void(const std::string&)> say = [](const std::string&) {};
};

// One mouse position in a view panel with the modifier keys held.
struct PointerEvent {
  Vec2 pixel{0.0};
  ViewRect rect;
  bool shift = false, ctrl = false, alt = false;
  std::optional<Vec3> axis;           // X, Y or Z held: constrain motion to that world axis
  const PickResult* under = nullptr;  // what lies under the cursor (at a click: at the press)

  SelectMode select_mode() const {
    return ctrl ? SelectMode::Toggle : shift ? SelectMode::Add : SelectMode::Replace;
  }
};

class Tool {
 public:
  virtual ~Tool() = default;
  virtual std::string name() const = 0;
  // What the tool does, for the status bar while it is active.
  virtual std::string hint() const = 0;
  // The key that activates it ("V"; empty: none), bound through the action table.
  virtual std::string shortcut() const { return {}; }

  // A left press in a view. Returns true when the tool takes the mouse: it then gets drag() at
  // every cursor position and release() at the end. Returns false to let the press orbit the
  // view; a press and release without motion then comes back as click().
  virtual bool press(ToolContext& ctx, const PointerEvent& e) = 0;
  virtual void drag(ToolContext&, const PointerEvent&) {}
  virtual void release(ToolContext&, const PointerEvent&) {}
  virtual void click(ToolContext&, const PointerEvent&) {}
  // Esc, an undo or a new document while the tool holds the mouse: drop what is under way.
  virtual void cancel(ToolContext&) {}
  virtual bool capturing() const { return false; }
};

class ToolBox {
 public:
  // The first tool added is the default one (active at start and after Esc).
  void add(std::unique_ptr<Tool> tool);
  std::size_t size() const { return tools_.size(); }
  Tool& tool(std::size_t i) { return *tools_.at(i); }
  Tool& active() { return *tools_.at(active_); }
  std::size_t active_index() const { return active_; }
  // Makes tool i active, cancelling what the current one holds. Returns false for a bad index.
  bool activate(std::size_t i, ToolContext& ctx);

 private:
  std::vector<std::unique_ptr<Tool>> tools_;
  std::size_t active_ = 0;
};

}  // namespace pl
