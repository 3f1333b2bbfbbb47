#include "app/document/command.hpp"

#include <cassert>

namespace pl {

MovePointsCommand::MovePointsCommand(std::vector<PointRef> refs, std::vector<Vec3> positions,
                                     HandleMode mode, bool nudge)
    : refs_(std::move(refs)), positions_(std::move(positions)), mode_(mode), nudge_(nudge) {
  assert(refs_.size() == positions_.size());
}

void MovePointsCommand::apply(Scene& scene) {
  for (const PointRef& r : refs_)
    if (!point_exists(scene, r)) throw EditRefused("no such point: " + describe(r));
  move_points(scene, refs_, positions_, mode_);
}

std::string MovePointsCommand::label() const {
  const std::string verb = nudge_ ? "nudge " : "move ";
  return refs_.size() == 1 ? verb + describe(refs_[0])
                           : verb + std::to_string(refs_.size()) + " points";
}

std::string MovePointsCommand::merge_key() const {
  if (!nudge_) return {};
  std::string key = "nudge";
  for (const PointRef& r : refs_) {
    key += ';';
    key += describe(r);
  }
  return key;
}

void move_points(Scene& scene, const std::vector<PointRef>& refs,
                 const std::vector<Vec3>& positions, HandleMode mode,
                 const std::vector<std::optional<Vec3>>& free_defaults) {
  // Vertices first: they carry their handles, which may then move themselves.
  for (std::size_t i = 0; i < refs.size(); ++i)
    if (refs[i].kind == PointRef::Kind::NetworkVertex)
      set_point_position(scene, refs[i], positions[i]);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const PointRef& r = refs[i];
    if (r.kind == PointRef::Kind::PatchPoint || r.kind == PointRef::Kind::CurvePoint)
      set_point_position(scene, r, positions[i]);
    if (r.kind != PointRef::Kind::EdgeHandle) continue;
    Network& net = *scene.network;
    if (mode == HandleMode::RotatePlane) {
      move_handle_turning_plane(net, r.object, r.index, positions[i]);
    } else {
      // The other moving handles at this vertex do not hold the plane.
      const int v = net.edges[r.object].v[r.index];
      std::vector<int> others;
      for (std::size_t j = 0; j < refs.size(); ++j)
        if (j != i && refs[j].kind == PointRef::Kind::EdgeHandle &&
            net.edges[refs[j].object].v[refs[j].index] == v)
          others.push_back(refs[j].object);
      net.edges[r.object].handles[r.index] =
          constrained_handle(net, r.object, r.index, positions[i], others);
    }
  }
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (refs[i].kind != PointRef::Kind::FreePoint) continue;
    if (i < free_defaults.size() && free_defaults[i])
      set_free_point_offset(scene, refs[i], positions[i] - *free_defaults[i]);
    else
      set_point_position(scene, refs[i], positions[i]);
  }
}

}  // namespace pl
