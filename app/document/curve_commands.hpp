// The editing commands of free curves, each one undo step on the document: add a curve, delete
// curves, move a control point (a run of moves of the same point within the merge window is one
// step: a drag or nudges), type a weight, insert a knot, elevate the degree, split, reverse. The
// geometry is core's (core/curve/scene_curve.hpp); a command refuses (EditRefused, the document
// unchanged) what would leave a curve the reader rejects.
#pragma once

#include <string>
#include <vector>

#include "app/document/command.hpp"

namespace pl {

// Appends a curve of `type` through/with `points` as the new-curve tool collects them: a Bézier
// of the points, a clamped uniform cubic (or lower, for few points) B-spline or NURBS (weights 1),
// the interpolating cubic of four points, or the Hermite curve from the first to the last point
// with the chords as tangents.
class AddCurveCommand final : public Command {
 public:
  AddCurveCommand(CurveType type, std::vector<Vec3> points)
      : type_(type), points_(std::move(points)) {}
  void apply(Scene& scene) override;
  std::string label() const override;
  int curve() const { return curve_; }  // after apply

 private:
  CurveType type_;
  std::vector<Vec3> points_;
  int curve_ = -1;
};

// Deletes the free curves `curves` (in any order; a curve named twice is deleted once); the
// curves after them move down. Refused: a curve that does not exist, or none named.
class DeleteCurvesCommand final : public Command {
 public:
  explicit DeleteCurvesCommand(std::vector<int> curves);
  void apply(Scene& scene) override;
  std::string label() const override;  // "delete curve 2", "delete curves 0, 3"
  const std::vector<int>& removed() const { return curves_; }  // increasing, indices before it

 private:
  std::vector<int> curves_;
};

// An edit of control point `point` of curve `curve`: refused where the curve has no such point,
// where the edit itself refuses, or where it would leave a curve the reader rejects. The label
// names the point: "<what> curve 2 point 5".
class CurvePointCommand : public Command {
 public:
  void apply(Scene& scene) final;
  std::string label() const final;

 protected:
  CurvePointCommand(const char* what, int curve, int point)
      : what_(what), curve_(curve), point_(point) {}

 private:
  // The edit itself, on a curve that has the point.
  virtual void edit(SceneCurve& curve, int point) const = 0;

  const char* what_;
  int curve_, point_;
};

class MoveCurvePointCommand final : public CurvePointCommand {
 public:
  MoveCurvePointCommand(int curve, int point, Vec3 position)
      : CurvePointCommand("move", curve, point), position_(position) {}
  std::string merge_key() const override { return label(); }

 private:
  void edit(SceneCurve& curve, int point) const override;
  Vec3 position_;
};

// A NURBS weight (a B-spline becomes a NURBS curve); refused unless finite and positive.
class SetCurveWeightCommand final : public CurvePointCommand {
 public:
  SetCurveWeightCommand(int curve, int point, double weight)
      : CurvePointCommand("weight of", curve, point), weight_(weight) {}

 private:
  void edit(SceneCurve& curve, int point) const override;
  double weight_;
};

// The curve operations that keep the point set of the curve: knot insertion at t, degree
// elevation, split at t (the second piece is inserted after the first), reverse.
class CurveOperationCommand final : public Command {
 public:
  enum class Operation { InsertKnot, ElevateDegree, Split, Reverse };
  CurveOperationCommand(int curve, Operation op, double t = 0) : curve_(curve), op_(op), t_(t) {}
  void apply(Scene& scene) override;
  std::string label() const override;

 private:
  int curve_;
  Operation op_;
  double t_;
};

}  // namespace pl
