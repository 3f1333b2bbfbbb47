#include "app/document/transform_command.hpp"

#include <array>

#include "core/network/network_transform.hpp"

namespace pl {

void TransformPointsCommand::apply(Scene& scene) {
  if (refs_.empty()) throw EditRefused("nothing selected to transform");
  if (!transform_.valid())
    throw EditRefused("not a rotation, scale or move (non-finite or degenerate)");
  for (const PointRef& r : refs_)
    if (!point_exists(scene, r)) throw EditRefused("no such point: " + describe(r));
  // Where the points that are not part of the network go, read before the network moves (a
  // free point's position depends on it).
  std::vector<Vec3> targets;
  for (const PointRef& r : refs_) targets.push_back(transform_.point(point_position(scene, r)));

  std::vector<int> vertices;
  std::vector<std::array<int, 2>> handles;
  for (const PointRef& r : refs_) {
    if (r.kind == PointRef::Kind::NetworkVertex) vertices.push_back(r.index);
    if (r.kind == PointRef::Kind::EdgeHandle) handles.push_back({r.object, r.index});
  }
  if (!vertices.empty() || !handles.empty())
    transform_network(*scene.network, vertices, handles, transform_);
  for (std::size_t i = 0; i < refs_.size(); ++i) {
    const PointRef& r = refs_[i];
    if (r.kind == PointRef::Kind::PatchPoint || r.kind == PointRef::Kind::CurvePoint)
      set_point_position(scene, r, targets[i]);
  }
  for (std::size_t i = 0; i < refs_.size(); ++i)
    if (refs_[i].kind == PointRef::Kind::FreePoint) set_point_position(scene, refs_[i], targets[i]);
}

std::string TransformPointsCommand::label() const {
  const glm::dmat3 identity(1.0);
  const std::string verb = transform_.rotation != identity ? "rotate "
                           : transform_.scale != 1         ? "scale "
                                                           : "move ";
  return refs_.size() == 1 ? verb + describe(refs_[0])
                           : verb + std::to_string(refs_.size()) + " points";
}

}  // namespace pl
