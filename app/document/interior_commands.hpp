// The commands on the interior of a network GB face (docs/scene-format.md, "Interior control"):
// its degree and the offsets of its free points. Moving a free point is a MovePointsCommand (or a
// drag) on its PointRef. A Gregory face has no free interior: both commands refuse it.
#pragma once

#include "app/document/command.hpp"

namespace pl {

// Sets the degree of GB face `face` (3 ... kMaxGBFaceDegree). The offsets are re-fitted to the
// new degree (gb_face_offsets_for_degree): the boundary and its G1 data never change, and the
// interior stays as close as the new degree allows.
class SetFaceDegreeCommand final : public Command {
 public:
  SetFaceDegreeCommand(int face, int degree) : face_(face), degree_(degree) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  int face_, degree_;
};

// Puts every free point of GB face `face` back at its default (the offsets cleared; the degree
// stays).
class ResetInteriorCommand final : public Command {
 public:
  explicit ResetInteriorCommand(int face) : face_(face) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  int face_;
};

// Why face `face` has no free interior to edit ("" when it has one: a GB face).
std::string no_interior_reason(const Scene& scene, int face);

}  // namespace pl
