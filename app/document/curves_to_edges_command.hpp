// Free curves turned into network edges, one undo step: each curve a chain of cubic Bézier spans
// (core/curve/cubic_fit.hpp: exact for a curve that is one cubic, else fitted within the
// tolerance), each span an edge. A span end lands on an existing network vertex within the
// tolerance, so curves drawn to meet, and curves ending on the network, connect; elsewhere it
// makes a new vertex. A closed curve (its ends within the tolerance) becomes three chains at
// least, so that no two of its edges join the same vertices. The curves leave the free curves.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

// The tolerance used when none is given: this fraction of the diagonal of the curves' control
// points' bounding box.
constexpr double kCurveFitRelativeTolerance = 1e-4;

class CurvesToEdgesCommand final : public Command {
 public:
  // Refused (EditRefused, nothing changed): no curve or a missing one, a tolerance that is not
  // positive, a curve that needs more than 256 spans or is broken in two, a span whose ends land
  // on one vertex or on two that an edge already joins.
  explicit CurvesToEdgesCommand(std::vector<int> curves,
                                std::optional<double> tolerance = std::nullopt)
      : curves_(std::move(curves)), tolerance_(tolerance) {}
  void apply(Scene& scene) override;
  // "curve 2 to 3 network edges (fitted within 0.0001)", "curves 0, 1 to 2 network edges (exact)".
  std::string label() const override;
  const std::vector<int>& edges() const { return edges_; }  // after apply: the new edges

 private:
  std::vector<int> curves_;
  std::optional<double> tolerance_;
  std::vector<int> edges_;
  double size_ = 0, used_tolerance_ = 0, deviation_ = 0;
};

}  // namespace pl
