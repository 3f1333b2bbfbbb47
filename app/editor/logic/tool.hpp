// The active tool: what a left press in the view does. The select tool picks and drags; the
// authoring tools (add a vertex on the work plane, add an edge, make a face, split an edge) are
// further Tool classes, added to the ToolBox with one line and given an action (menu entry and
// key). A tool sees the mouse as PointerEvents, what lies under the cursor (the picker's result)
// and acts on the document through commands; what it shows while it works (the rubber band, the
// point a click would add) is a ToolPreview the editor draws. Every tool is GUI-free and
// unit-tested.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/document/document.hpp"
#include "app/document/network_commands.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/selection.hpp"
#include "app/editor/logic/snapping.hpp"
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
  double ui_scale = 1;  // on-screen handles are this many times their nominal pixel size
};

// Runs a command for a tool or an action. The status line gets the command's label, or the
// reason it was refused (EditRefused: the document is unchanged). The caller keeps its pointer,
// so it can read what the command did (the faces a split changed, what a delete removed).
// Returns whether it ran.
bool run_command(Document& doc, const std::function<void(const std::string&)>& say,
                 std::shared_ptr<Command> command);
bool run_command(ToolContext& ctx, std::shared_ptr<Command> command);

// What a tool shows over the view while it works, in world coordinates (the editor projects and
// draws it): what has been picked (its points marked, its lines solid), what a click or Enter
// would add (dashed: the rubber band to the cursor, the edge closing a face) and the point a
// click acts on.
struct ToolPreview {
  std::vector<Vec3> picked;                  // marked points (the vertices picked so far)
  std::vector<std::vector<Vec3>> lines;      // solid polylines (picked edges, the chain so far)
  std::vector<std::array<Vec3, 2>> pending;  // dashed segments
  std::optional<Vec3> target;                // where a click acts now
  bool empty() const { return picked.empty() && lines.empty() && pending.empty() && !target; }
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
  // `shortcut`: the key that activates it ("V"; empty: none), bound through the action table.
  Tool(std::string name, std::string shortcut)
      : name_(std::move(name)), shortcut_(std::move(shortcut)) {}
  virtual ~Tool() = default;
  const std::string& name() const { return name_; }
  const std::string& shortcut() const { return shortcut_; }
  // What the tool does, for the status bar while it is active.
  virtual std::string hint() const = 0;

  // A left press in a view. Returns true when the tool takes the mouse: it then gets drag() at
  // every cursor position and release() at the end. Returns false to let the press orbit the
  // view; a press and release without motion then comes back as click().
  virtual bool press(ToolContext& ctx, const PointerEvent& e) = 0;
  virtual void drag(ToolContext&, const PointerEvent&) {}
  virtual void release(ToolContext&, const PointerEvent&) {}
  virtual void click(ToolContext&, const PointerEvent&) {}
  // The cursor over a view with no button held (what preview() shows follows it).
  virtual void hover(ToolContext&, const PointerEvent&) {}
  // The cursor left the views.
  virtual void leave() {}
  // Esc, an undo that renumbered the network or a new document: drop what is under way.
  virtual void cancel(ToolContext&) {}
  // Holds the mouse or has picked something a further click or Enter will use (Esc cancels it).
  virtual bool capturing() const { return false; }
  // Enter: completes what has been picked (a face's loop). can_finish() says whether it would.
  virtual bool can_finish(const ToolContext&) const { return false; }
  virtual void finish(ToolContext&) {}
  virtual ToolPreview preview(const ToolContext&) const { return {}; }
  // Clicks put points on the work plane: the editor shows its grid while the tool is chosen.
  virtual bool places_on_work_plane() const { return false; }

 private:
  std::string name_, shortcut_;
};

// A tool that acts on clicks only (a press orbits; press and release without motion is a click)
// and shows where a click would act: the point under the cursor that hover() finds, none once
// the cursor left the views.
class ClickTool : public Tool {
 public:
  using Tool::Tool;
  bool press(ToolContext&, const PointerEvent&) override { return false; }
  void leave() override { cursor_.reset(); }

 protected:
  std::optional<Vec3> cursor_;
};

// How near (in pixels, times the UI scale) a scene point must be for a new point to snap to it.
inline constexpr double kSnapRadiusPx = 10;
// With snapping on and Alt not held: the scene point near the cursor a new point snaps to, else
// (off a surface) the work plane's grid point; nullopt otherwise (snapping.hpp).
std::optional<Snapped> snapping(const ToolContext& ctx, const PointerEvent& e);
// Where a click at `e` puts a new point: where it snaps (snapping), else on the surface under
// the cursor, else where the cursor's ray meets the work plane (nullopt when it does not, in
// front of the eye).
std::optional<Vec3> placement(const ToolContext& ctx, const PointerEvent& e);
// The same with the snap already found (snapping(ctx, e)), so a caller that also reports it
// searches the scene once.
std::optional<Vec3> placement(const ToolContext& ctx, const PointerEvent& e,
                              const std::optional<Snapped>& snapped);
// The network vertex under the cursor at `e`, or -1.
int vertex_under(const PointerEvent& e);

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
