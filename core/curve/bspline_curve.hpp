// B-spline curve of degree p on any (uniform or non-uniform, clamped or not) knot vector:
// C(t) = sum_i N_{i,p}(t) P_i for t in [knots[p], knots[n]], evaluated from the basis
// recursion with exact derivatives; Boehm knot insertion and Bézier extraction.
#pragma once

#include <glm/vec4.hpp>
#include <vector>

#include "core/curve/bezier_curve.hpp"

namespace pl {

class BSplineCurve {
 public:
  // Throws std::invalid_argument for an invalid knot vector (see validate_knots).
  BSplineCurve(int degree, std::vector<double> knots, std::vector<Vec3> points);

  // Uniform clamped knots: degree+1 equal end knots, interior knots equally spaced in [0,1].
  static std::vector<double> clamped_uniform_knots(int degree, std::size_t points);

  int degree() const { return p_; }
  const std::vector<double>& knots() const { return knots_; }
  const std::vector<Vec3>& control_points() const { return points_; }
  double t_min() const { return knots_[p_]; }
  double t_max() const { return knots_[points_.size()]; }

  CurvePoint evaluate(double t) const;
  double curvature(double t) const;
  // The same curve with knot t inserted once (t inside [t_min, t_max]; multiplicity stays <= p).
  BSplineCurve inserted(double t) const;
  // One Bézier curve per non-empty span, each over [0,1] of its span.
  std::vector<BezierCurve> bezier_pieces() const;

 private:
  int p_;
  std::vector<double> knots_;
  std::vector<Vec3> points_;
};

// Boehm's algorithm on homogeneous points (NURBS use w P and w): inserts t once into knots and
// updates points in place.
void insert_knot(int p, std::vector<double>& knots, std::vector<glm::dvec4>& points, double t);
// Throws std::invalid_argument unless knot t can be inserted once into a curve of degree p with
// `count` points: t in [knots[p], knots[count]] (the curve's range) and its multiplicity below p.
void check_knot_insertion(int p, const std::vector<double>& knots, std::size_t count, double t);
// Inserts every knot needed so each span's p+1 control points are its Bézier points.
void make_bezier_spans(int p, std::vector<double>& knots, std::vector<glm::dvec4>& points);

}  // namespace pl
