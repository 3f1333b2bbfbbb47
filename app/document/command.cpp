#include "app/document/command.hpp"

#include <cassert>

namespace pl {

MovePointsCommand::MovePointsCommand(std::vector<PointRef> refs, std::vector<Vec3> positions)
    : refs_(std::move(refs)), positions_(std::move(positions)) {
  assert(refs_.size() == positions_.size());
}

void MovePointsCommand::apply(Scene& scene) const {
  for (std::size_t i = 0; i < refs_.size(); ++i) set_point_position(scene, refs_[i], positions_[i]);
}

std::string MovePointsCommand::label() const {
  return refs_.size() == 1 ? "move " + describe(refs_[0])
                           : "move " + std::to_string(refs_.size()) + " points";
}

}  // namespace pl
