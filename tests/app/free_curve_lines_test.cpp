// Free curves in the editor: their control points are scene points that drag through the
// document like every other point (one undo step), and the drawn polyline follows a drag by
// recomputing only the spans the moved point touches, ending equal to a fresh sampling.
#include "app/editor/logic/free_curve_lines.hpp"

#include <gtest/gtest.h>

#include "render/draw_scene_builder.hpp"
#include "app/document/curve_commands.hpp"
#include "app/document/document.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/point_names.hpp"
#include "core/curve/bspline_curve.hpp"

namespace pl::test {
namespace {

std::vector<Vec3> zigzag(int n) {
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) p.push_back({double(i), double(i % 2), 0.25 * (i % 3)});
  return p;
}

double max_distance(const Polyline& a, const Polyline& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    worst = std::max(worst, glm::length(a[i] - b[i]));
  return worst;
}

TEST(FreeCurveLines, DragUpdatesOnlyTheMovedSpansAndMatchesAFreshSampling) {
  for (CurveType type : {CurveType::BSpline, CurveType::Nurbs, CurveType::Bezier}) {
    SceneCurve c;
    c.type = type;
    c.points = zigzag(type == CurveType::Bezier ? 6 : 200);
    if (type != CurveType::Bezier) {
      c.degree = 3;
      c.knots = BSplineCurve::clamped_uniform_knots(3, c.points.size());
    }
    if (type == CurveType::Nurbs)
      for (std::size_t i = 0; i < c.points.size(); ++i) c.weights.push_back(1.0 + 0.1 * (i % 4));
    std::vector<SceneCurve> curves{c};
    FreeCurveLines lines;
    std::vector<Polyline> drawn;
    lines.rebuild(curves, drawn);
    ASSERT_EQ(drawn.size(), 1u);
    const std::size_t all = drawn[0].size();
    curves[0].points[3] += Vec3(0.3, -0.7, 0.2);
    ASSERT_TRUE(lines.update(curves, drawn));
    // An independent sampling: every parameter evaluated from the curve's definition.
    EXPECT_LE(max_distance(drawn[0], free_curve_polyline(curves[0])), 1e-12) << int(type);
    if (type != CurveType::Bezier) {
      // A cubic point moves 4 of the 197 spans.
      const std::size_t per_span = free_curve_samples_per_span(curves[0]);
      EXPECT_LE(lines.last_update_samples(), 4 * per_span + 1);
      EXPECT_LT(lines.last_update_samples() * 20, all);
    }
    // A knot insertion (a change of shape, not a move) re-samples the curve.
    curves[0] = curve_knot_inserted(curves[0], 0.5 * (curves[0].t_min() + curves[0].t_max()));
    ASSERT_TRUE(lines.update(curves, drawn));
    EXPECT_LE(max_distance(drawn[0], free_curve_polyline(curves[0])), 1e-12);
    curves.push_back(c);
    EXPECT_FALSE(lines.update(curves, drawn));  // a new curve: rebuild
  }
}

TEST(FreeCurveLines, CurvePointsDragThroughTheDocumentAsOneStep) {
  Document doc;
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::BSpline, zigzag(6)));
  LiveSurfaces live(doc.scene(), 8, std::nullopt, "test", doc.revision());
  const auto ref = parse_point_name("curve 0 point 2");
  ASSERT_TRUE(ref);
  EXPECT_EQ(describe(*ref), "curve 0 point 2");
  const int index = live.points().find(*ref);
  ASSERT_GE(index, 0);
  EXPECT_EQ(live.points().positions[index], doc.scene().curves[0].points[2]);
  // The polygon joins consecutive points of the curve.
  const int next = live.points().find(PointRef::curve_point(0, 3));
  bool joined = false;
  for (const auto& s : live.points().segments) joined |= (int(s[0]) == index && int(s[1]) == next);
  EXPECT_TRUE(joined);

  doc.begin_drag({*ref});
  for (int k = 1; k <= 5; ++k) {
    doc.drag_to({Vec3(2, 0.2 * k, 1)});
    live.sync(doc.scene(), doc.revision());
    EXPECT_EQ(live.points().positions[index], Vec3(2, 0.2 * k, 1));
    EXPECT_LE(max_distance(live.draw().free_curves[0], free_curve_polyline(doc.scene().curves[0])),
              1e-12);
  }
  doc.end_drag();
  // One undo step takes the whole drag back and nothing else.
  ASSERT_TRUE(doc.undo());
  ASSERT_EQ(doc.scene().curves.size(), 1u);
  EXPECT_EQ(doc.scene().curves[0].points[2], zigzag(6)[2]);
  live.sync(doc.scene(), doc.revision());
  EXPECT_EQ(live.points().positions[index], zigzag(6)[2]);
}

}  // namespace
}  // namespace pl::test
