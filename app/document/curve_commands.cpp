#include "app/document/curve_commands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/curve/bspline_curve.hpp"

namespace pl {

namespace {

SceneCurve& curve_at(Scene& scene, int c) {
  if (c < 0 || c >= int(scene.curves.size()))
    throw EditRefused("curve " + std::to_string(c) + " does not exist");
  return scene.curves[c];
}

// The edited curve must still be one the reader accepts.
void check(const SceneCurve& c) {
  try {
    validate_curve(c);
  } catch (const std::invalid_argument& e) {
    throw EditRefused(e.what());
  }
}

}  // namespace

void AddCurveCommand::apply(Scene& scene) {
  SceneCurve c;
  c.type = type_;
  const std::size_t n = points_.size();
  switch (type_) {
    case CurveType::Bezier:
      c.points = points_;
      break;
    case CurveType::Interpolating:
      if (n != 4) throw EditRefused("an interpolating cubic takes 4 points");
      c.points = points_;
      break;
    case CurveType::Hermite:
      if (n < 2) throw EditRefused("a Hermite curve takes at least 2 points");
      c.points = {points_.front(), points_.back()};
      c.tangents = {points_[1] - points_[0], points_[n - 1] - points_[n - 2]};
      break;
    case CurveType::BSpline:
    case CurveType::Nurbs: {
      if (n < 2) throw EditRefused("a B-spline takes at least 2 points");
      c.degree = std::min<int>(3, static_cast<int>(n) - 1);
      c.points = points_;
      c.knots = BSplineCurve::clamped_uniform_knots(c.degree, n);
      if (type_ == CurveType::Nurbs) c.weights.assign(n, 1.0);
      break;
    }
  }
  check(c);
  curve_ = static_cast<int>(scene.curves.size());
  scene.curves.push_back(std::move(c));
}

std::string AddCurveCommand::label() const {
  return "add " + std::string(curve_type_name(type_)) + " curve";
}

DeleteCurvesCommand::DeleteCurvesCommand(std::vector<int> curves) : curves_(std::move(curves)) {
  std::sort(curves_.begin(), curves_.end());
  curves_.erase(std::unique(curves_.begin(), curves_.end()), curves_.end());
}

void DeleteCurvesCommand::apply(Scene& scene) {
  if (curves_.empty()) throw EditRefused("no curve to delete");
  for (int c : curves_) curve_at(scene, c);  // each must exist
  // From the last: the indices still to delete keep their curves.
  for (auto c = curves_.rbegin(); c != curves_.rend(); ++c)
    scene.curves.erase(scene.curves.begin() + *c);
}

std::string DeleteCurvesCommand::label() const {
  std::string s = curves_.size() == 1 ? "delete curve " : "delete curves ";
  for (std::size_t i = 0; i < curves_.size(); ++i)
    s += (i ? ", " : "") + std::to_string(curves_[i]);
  return s;
}

void CurvePointCommand::apply(Scene& scene) {
  SceneCurve& c = curve_at(scene, curve_);
  if (point_ < 0 || point_ >= int(c.points.size()))
    throw EditRefused("curve " + std::to_string(curve_) + " has no point " +
                      std::to_string(point_));
  edit(c, point_);
  check(c);
}

std::string CurvePointCommand::label() const {
  return std::string(what_) + " curve " + std::to_string(curve_) + " point " +
         std::to_string(point_);
}

void MoveCurvePointCommand::edit(SceneCurve& c, int point) const {
  c.points[point] = position_;
}

void SetCurveWeightCommand::edit(SceneCurve& c, int point) const {
  if (c.type != CurveType::BSpline && c.type != CurveType::Nurbs)
    throw EditRefused("only B-spline and NURBS curves have weights");
  if (!(weight_ > 0) || !std::isfinite(weight_))
    throw EditRefused("a weight must be positive and finite");
  if (c.type == CurveType::BSpline) {
    c.type = CurveType::Nurbs;
    c.weights.assign(c.points.size(), 1.0);
  }
  c.weights[point] = weight_;
}

void CurveOperationCommand::apply(Scene& scene) {
  SceneCurve& c = curve_at(scene, curve_);
  try {
    switch (op_) {
      case Operation::InsertKnot:
        c = curve_knot_inserted(c, t_);
        break;
      case Operation::ElevateDegree:
        c = curve_degree_elevated(c);
        break;
      case Operation::Reverse:
        c = curve_reversed(c);
        break;
      case Operation::Split: {
        auto [a, b] = curve_split(c, t_);
        check(a);
        check(b);
        c = std::move(a);
        scene.curves.insert(scene.curves.begin() + curve_ + 1, std::move(b));
        return;
      }
    }
  } catch (const std::invalid_argument& e) {
    throw EditRefused(e.what());
  }
  check(scene.curves[curve_]);
}

std::string CurveOperationCommand::label() const {
  const std::string c = "curve " + std::to_string(curve_);
  switch (op_) {
    case Operation::InsertKnot:
      return "insert knot in " + c;
    case Operation::ElevateDegree:
      return "elevate degree of " + c;
    case Operation::Split:
      return "split " + c;
    case Operation::Reverse:
      return "reverse " + c;
  }
  return c;
}

}  // namespace pl
