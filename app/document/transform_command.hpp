// Move, rotate and scale a selection's points about a pivot as one undo step: the network part
// as one rigid piece (core/network/network_transform.hpp: vertices carry their handles and turn
// their tangent planes), explicit patch and free-curve control points transformed, free interior
// points of GB faces carried as positions (their offsets follow the new defaults).
#pragma once

#include <string>
#include <vector>

#include "app/document/command.hpp"
#include "core/math/similarity.hpp"

namespace pl {

class TransformPointsCommand final : public Command {
 public:
  // Refused at apply (EditRefused): no points, a point that does not exist, an invalid
  // similarity.
  TransformPointsCommand(std::vector<PointRef> refs, Similarity transform)
      : refs_(std::move(refs)), transform_(transform) {}
  void apply(Scene& scene) override;
  // "rotate 5 points", "scale vertex 3", "move 2 points" (by what the similarity does).
  std::string label() const override;

 private:
  std::vector<PointRef> refs_;
  Similarity transform_;
};

}  // namespace pl
