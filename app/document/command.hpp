// Every edit is a command on the document. UI code never mutates geometry
// directly. Undo does not invert a command: the document keeps the scene before and after it
// (patches are shared and copied on write, so that is cheap), which makes undo bit-exact even
// where a command moves several things at once.
//
// A command applies itself to a copy of the scene; if it throws (EditRefused: a request that
// would make the scene invalid, with a message for the designer) the document is unchanged.
// The network commands are in network_commands.hpp.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/document/point_ref.hpp"
#include "core/network/handle_planes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

class Command {
 public:
  virtual ~Command() = default;
  // Applies the edit (once). Throws EditRefused, leaving `scene` in any state: the document
  // applies commands to a copy.
  virtual void apply(Scene& scene) = 0;
  // What the edit did, for the undo menu and the status bar; may say more after apply() (a
  // split edge names the faces that gained a side).
  virtual std::string label() const = 0;
  // Commands with the same non-empty key, executed one after the other within a moment, are one
  // undo step (arrow-key nudges of the same points, a dragged normal).
  virtual std::string merge_key() const { return {}; }
};

// Moves points to new positions (a typed coordinate, a nudge; drags go through the document).
// Vertices move first, carrying their handles; handles then move as `mode` says (HandleMode:
// kept in their vertex's tangent plane by default). `nudge`: an arrow-key step, merged with the
// previous nudge of the same points.
class MovePointsCommand final : public Command {
 public:
  MovePointsCommand(std::vector<PointRef> refs, std::vector<Vec3> positions,
                    HandleMode mode = HandleMode::KeepPlane, bool nudge = false);
  void apply(Scene& scene) override;
  std::string label() const override;
  std::string merge_key() const override;
  const std::vector<PointRef>& refs() const { return refs_; }

 private:
  std::vector<PointRef> refs_;
  std::vector<Vec3> positions_;
  HandleMode mode_;
  bool nudge_;
};

// Moves the points of `refs` to `positions` in `scene` (MovePointsCommand's edit, also each
// frame of a drag). Every ref must exist. Free points move last, against the defaults of the
// network as moved; `free_defaults` (one per ref, or empty) gives them when known (a drag that
// moves no network point), so a frame does not rebuild them.
void move_points(Scene& scene, const std::vector<PointRef>& refs,
                 const std::vector<Vec3>& positions, HandleMode mode,
                 const std::vector<std::optional<Vec3>>& free_defaults = {});

}  // namespace pl
