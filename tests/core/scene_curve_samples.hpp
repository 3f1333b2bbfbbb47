// Free curves the curve tests share: a Bézier of given points and the exact NURBS circle.
#pragma once

#include <vector>

#include "core/curve/nurbs_curve.hpp"
#include "core/curve/scene_curve.hpp"

namespace pl::test {

inline SceneCurve bezier_scene_curve(std::vector<Vec3> points) {
  SceneCurve c;
  c.type = CurveType::Bezier;
  c.points = std::move(points);
  return c;
}

// The rational quadratic circle of radius r about `center` in the plane z = center.z.
inline SceneCurve circle_scene_curve(Vec3 center, double r) {
  const NurbsCurve n = NurbsCurve::circle(center, Vec3(1, 0, 0), Vec3(0, 1, 0), r);
  SceneCurve c;
  c.type = CurveType::Nurbs;
  c.degree = 2;
  c.knots = n.knots();
  c.points = n.control_points();
  c.weights = n.weights();
  return c;
}

}  // namespace pl::test
