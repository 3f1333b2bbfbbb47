// NURBS curve: C(t) = sum N_{i,p}(t) w_i P_i / sum N_{i,p}(t) w_i with positive weights.
// Conics are exact, e.g. circle() below.
#pragma once

#include <vector>

#include "core/curve/bezier_curve.hpp"

namespace pl {

class NurbsCurve {
 public:
  // Throws std::invalid_argument for invalid knots or non-positive/non-finite weights.
  NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points,
             std::vector<double> weights);

  // Full circle of radius r about `center` in the plane spanned by unit vectors x, y: 9 points,
  // quadratic, weights 1 and sqrt(2)/2, knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}.
  static NurbsCurve circle(Vec3 center, Vec3 x, Vec3 y, double r);
  // Half circle from center + r x through center + r y to center - r x: 5 points, quadratic.
  static NurbsCurve half_circle(Vec3 center, Vec3 x, Vec3 y, double r);

  int degree() const { return p_; }
  const std::vector<double>& knots() const { return knots_; }
  const std::vector<Vec3>& control_points() const { return points_; }
  const std::vector<double>& weights() const { return weights_; }
  double t_min() const { return knots_[p_]; }
  double t_max() const { return knots_[points_.size()]; }

  CurvePoint evaluate(double t) const;
  double curvature(double t) const;
  NurbsCurve inserted(double t) const;  // same curve, knot t inserted (homogeneous Boehm)

 private:
  int p_;
  std::vector<double> knots_;
  std::vector<Vec3> points_;
  std::vector<double> weights_;
};

void validate_weights(const std::vector<double>& w, std::size_t n);

}  // namespace pl
