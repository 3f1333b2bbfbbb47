// Picking: the triangle hierarchy against testing every triangle, and the scene picker on real
// evaluations (the default scene, a 1,536-face cube-sphere): faces under their own samples,
// edges under their curves (not through a surface), points before both.
#include <gtest/gtest.h>

#include <random>

#include "app/cli/load_input.hpp"
#include "app/editor/logic/live_surfaces.hpp"
#include "app/editor/logic/scene_picker.hpp"
#include "app/editor/logic/surface_probe.hpp"
#include "core/network/sample_networks.hpp"

namespace pl {
namespace {

const ViewRect kRect{0, 0, 900, 700};

Scene default_scene() {
  return load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json");
}

Camera framing(const DrawScene& d, ViewPreset preset = ViewPreset::Iso) {
  return preset_camera(preset, d.bounds(), kRect.aspect());
}

PickScene pick_scene(const LiveSurfaces& live, std::vector<SelectionItem>& items) {
  items = surface_items(live.surfaces());
  return {live.draw().surfaces, items, live.draw().network_curves, &live.points(),
          live.draw().free_curves};
}

// Same answer as testing every triangle: the same distance, and the same triangle unless two
// triangles are hit at exactly that distance (a shared edge or vertex).
void expect_same_hit(const std::optional<TriangleHit>& a, const std::optional<TriangleHit>& b,
                     const SurfaceMesh& m) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  EXPECT_EQ(a->t, b->t);
  if (a->triangle != b->triangle) {
    // A tie: both triangles share the hit point.
    const auto& ta = m.triangles[a->triangle];
    const auto& tb = m.triangles[b->triangle];
    int shared = 0;
    for (uint32_t i : ta)
      for (uint32_t j : tb) shared += i == j;
    EXPECT_GE(shared, 1);
  } else {
    EXPECT_EQ(a->b1, b->b1);
    EXPECT_EQ(a->b2, b->b2);
  }
}

TEST(EditorPicking, HierarchyAgreesWithEveryTriangle) {
  const LiveSurfaces live(default_scene(), 24, std::nullopt, "default");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-6, 6);
  const Camera c = framing(live.draw());
  int hits = 0;
  for (const SurfaceMesh& m : live.draw().surfaces) {
    const TriangleBvh bvh(m.positions, m.triangles);
    EXPECT_GT(bvh.node_count(), 1u);
    std::uniform_int_distribution<std::size_t> sample(0, m.positions.size() - 1);
    for (int k = 0; k < 400; ++k) {
      // Near a random sample (hits, misses past the border, shared edges and vertices).
      const Vec2 px = *project_to_window(c, kRect, m.positions[sample(rng)]);
      const Ray ray = window_ray(c, kRect, px + Vec2(jitter(rng), jitter(rng)));
      const auto ref = intersect_all(ray, m.positions, m.triangles, 1e300);
      const auto got = bvh.intersect(ray, m.positions, m.triangles, 1e300);
      expect_same_hit(got, ref, m);
      hits += ref.has_value();
    }
  }
  EXPECT_GT(hits, 600);  // the rays really hit the surfaces
}

TEST(EditorPicking, HierarchyOfAnEmptyOrTinyMesh) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<uint32_t, 3>> one{{0, 1, 2}}, none;
  const Ray down{{0.25, 0.25, 1}, {0, 0, -1}};
  const auto h = TriangleBvh(p, one).intersect(down, p, one, 1e300);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->triangle, 0);
  EXPECT_DOUBLE_EQ(h->t, 1.0);
  EXPECT_DOUBLE_EQ(h->b1, 0.25);
  EXPECT_DOUBLE_EQ(h->b2, 0.25);
  EXPECT_FALSE(TriangleBvh(p, one).intersect(down, p, one, 0.5));  // beyond t_max
  EXPECT_FALSE(TriangleBvh(p, none).intersect(down, p, none, 1e300));
}

TEST(EditorPicking, ClickingASurfaceSelectsItsFace) {
  const LiveSurfaces live(default_scene(), 24, std::nullopt, "default");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  const Camera c = framing(live.draw());
  ScenePicker picker;
  int checked = 0;
  for (std::size_t s = 0; s < live.draw().surfaces.size(); ++s) {
    const SurfaceMesh& m = live.draw().surfaces[s];
    // Triangle centres (well inside their triangle): the ray through one hits it, or
    // something in front of it.
    for (std::size_t i = 0; i < m.triangles.size(); i += 37) {
      const auto& tri = m.triangles[i];
      const Vec3 centre = (m.positions[tri[0]] + m.positions[tri[1]] + m.positions[tri[2]]) / 3.0;
      const auto px = project_to_window(c, kRect, centre);
      ASSERT_TRUE(px);
      const PickResult r = picker.pick(scene, c, kRect, *px, {false, false});
      ASSERT_TRUE(r.surface);
      const Ray ray = window_ray(c, kRect, *px);
      EXPECT_LE(r.surface->hit.t, glm::dot(centre - ray.origin, ray.direction) + 1e-9);
      if (r.surface->surface == int(s)) {
        ASSERT_TRUE(r.item);
        EXPECT_EQ(*r.item, SelectionItem::face(live.surfaces().surfaces[s].face));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 40);
  EXPECT_EQ(picker.stats().surfaces, live.draw().surfaces.size());
}

TEST(EditorPicking, PointsFirstThenCurvesThenSurfaces) {
  const LiveSurfaces live(default_scene(), 24, std::nullopt, "default");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  const Camera c = framing(live.draw(), ViewPreset::Top);
  ScenePicker picker;
  // A vertex: the point wins over the curves and faces meeting there.
  const Vec3 v2 = live.points().positions[live.points().find(PointRef::vertex(2))];
  PickResult r = picker.pick(scene, c, kRect, *project_to_window(c, kRect, v2));
  ASSERT_TRUE(r.item);
  EXPECT_EQ(*r.item, SelectionItem::of_point(PointRef::vertex(2)));
  // With points hidden, the same pixel is an edge at that vertex.
  r = picker.pick(scene, c, kRect, *project_to_window(c, kRect, v2), {false, true});
  ASSERT_TRUE(r.item);
  ASSERT_EQ(r.item->kind, SelectionItem::Kind::Edge);
  const Scene shipped = default_scene();  // kept alive: e refers into it
  const NetworkEdge& e = shipped.network->edges[r.item->index];
  EXPECT_TRUE(e.v[0] == 2 || e.v[1] == 2);
  // The middle of every edge's curve picks that edge (points hidden: handles may sit there).
  for (std::size_t k = 0; k < live.draw().network_curves.size(); ++k) {
    const Polyline& line = live.draw().network_curves[k];
    const Vec2 mid = *project_to_window(c, kRect, line[line.size() / 2]);
    r = picker.pick(scene, c, kRect, mid, {false, true});
    ASSERT_TRUE(r.item) << k;
    EXPECT_EQ(*r.item, SelectionItem::edge(int(k)));
    // The parameter there: the middle sample is at t = 1/2 (to the pixel's rounding).
    EXPECT_NEAR(r.edge_t, 0.5, 1e-6);
    // A few pixels off the curve (across it on screen) is still the edge; far off is not.
    const Vec2 along = *project_to_window(c, kRect, line[line.size() / 2 + 1]) - mid;
    const Vec2 across = glm::normalize(Vec2(-along.y, along.x));
    EXPECT_EQ(picker.pick(scene, c, kRect, mid + 4.0 * across, {false, true}).edge, int(k));
    EXPECT_NE(picker.pick(scene, c, kRect, mid + 40.0 * across, {false, true}).edge, int(k));
  }
  // Empty space: nothing.
  r = picker.pick(scene, c, kRect, Vec2(2, 2));
  EXPECT_FALSE(r.item);
  EXPECT_FALSE(r.surface);
  EXPECT_EQ(r.point, -1);
  EXPECT_EQ(r.edge, -1);
}

TEST(EditorPicking, FindsAPixelThatSelectsAFaceOrEdge) {
  const LiveSurfaces live(default_scene(), 24, std::nullopt, "default");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  const Camera c = framing(live.draw());
  ScenePicker picker;
  std::vector<SelectionItem> wanted{SelectionItem::face(0), SelectionItem::face(1)};
  for (int e = 0; e < int(live.draw().network_curves.size()); ++e)
    wanted.push_back(SelectionItem::edge(e));
  for (const SelectionItem& item : wanted) {
    const auto px = find_pixel_for(picker, scene, c, kRect, item);
    ASSERT_TRUE(px) << describe(item);
    const PickResult r = picker.pick(scene, c, kRect, *px);
    EXPECT_EQ(r.item, item);
    EXPECT_EQ(r.point, -1);  // no point lies there to grab instead
  }
  EXPECT_FALSE(find_pixel_for(picker, scene, c, kRect, SelectionItem::face(7)));
  EXPECT_FALSE(find_pixel_for(picker, scene, c, kRect, SelectionItem::edge(70)));
}

// A free curve is picked by its drawn line: a click near it selects the curve (not a point),
// with the point of the line under the cursor, from which the curve actions take their
// parameter; its points still win where they are; a network edge nearer the cursor wins.
TEST(EditorPicking, AFreeCurveIsPickedByItsLine) {
  Scene s = load_scene_file(std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets" / "curves" /
                       "bspline-knot-multiplicity.json");
  ASSERT_GE(s.curves.size(), 2u);
  const LiveSurfaces live(s, 8, std::nullopt, "curves");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  ASSERT_EQ(scene.free_curves.size(), s.curves.size());
  const Camera c = framing(live.draw(), ViewPreset::Top);
  ScenePicker picker;
  std::size_t picked = 0;
  for (std::size_t k = 0; k < s.curves.size(); ++k) {
    const SceneCurve& curve = s.curves[k];
    // A parameter in the middle of a span, away from the control points on screen.
    const auto spans = curve_spans(curve);
    const double t = 0.5 * (spans[spans.size() / 2].first + spans[spans.size() / 2].second);
    const Vec3 on = evaluate(curve, t).p;
    const Vec2 px = *project_to_window(c, kRect, on);
    bool near_point = false;
    for (const Vec3& q : curve.points)
      near_point |= glm::length(*project_to_window(c, kRect, q) - px) < 12;
    if (near_point) continue;
    const PickResult r = picker.pick(scene, c, kRect, px + Vec2(0, 3));
    ASSERT_TRUE(r.item) << k;
    EXPECT_EQ(*r.item, SelectionItem::curve(int(k)));
    EXPECT_EQ(r.curve, int(k));
    EXPECT_EQ(r.point, -1);
    // The picked point lies on the drawn line, within a few pixels of the cursor: the parameter
    // nearest to it is t (to the sampling of the search).
    EXPECT_LT(glm::length(*project_to_window(c, kRect, r.curve_point) - px), 4.0);
    // Far off: not the curve.
    EXPECT_NE(picker.pick(scene, c, kRect, px + Vec2(0, 60)).curve, int(k));
    // find_pixel_for finds a pixel that selects it, as scripts use it.
    const auto found = find_pixel_for(picker, scene, c, kRect, SelectionItem::curve(int(k)));
    ASSERT_TRUE(found) << k;
    EXPECT_EQ(picker.pick(scene, c, kRect, *found).item, SelectionItem::curve(int(k)));
    ++picked;
  }
  EXPECT_EQ(picked, s.curves.size());  // no curve skipped for a point near its middle
  // Curve points are of their own kind (drawn and named as curve points, not boundary ones).
  const int first = live.points().find(PointRef::curve_point(0, 0));
  ASSERT_GE(first, 0);
  EXPECT_EQ(live.points().kinds[first], ControlPointKind::Curve);
  // On a control point the point wins.
  const Vec2 p0 = *project_to_window(c, kRect, s.curves[0].points[0]);
  const PickResult r = picker.pick(scene, c, kRect, p0);
  ASSERT_TRUE(r.item);
  EXPECT_EQ(*r.item, SelectionItem::of_point(PointRef::curve_point(0, 0)));
  EXPECT_FALSE(find_pixel_for(picker, scene, c, kRect, SelectionItem::curve(70)));
}

TEST(EditorPicking, CurvesBehindASurfaceAreNotPicked) {
  // A closed cube-sphere: every curve on the back passes under some front surface pixel.
  Scene s;
  s.network = cube_sphere_network(2, FaceScheme::Auto);
  const LiveSurfaces live(s, 8, std::nullopt, "sphere");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  const Camera c = framing(live.draw(), ViewPreset::Front);
  ScenePicker picker;
  int back = 0, front = 0;
  for (std::size_t k = 0; k < live.draw().network_curves.size(); ++k) {
    const Polyline& line = live.draw().network_curves[k];
    const Vec3 p = line[line.size() / 2];
    const Vec2 px = *project_to_window(c, kRect, p);
    const PickResult r = picker.pick(scene, c, kRect, px, {false, true});
    // Faces towards the eye (front view looks along +y) are those with y < 0.
    if (p.y < -0.3) {
      EXPECT_EQ(r.edge, int(k));
      ++front;
    } else if (p.y > 0.3) {
      EXPECT_NE(r.edge, int(k));
      ASSERT_TRUE(r.surface);
      EXPECT_LT(r.surface->position.y, 0);  // the front surface is what lies there
      ++back;
    }
  }
  EXPECT_GT(front, 3);
  EXPECT_GT(back, 3);
}

TEST(EditorPicking, PointsInFrontOfTheSurfaceWinOverPointsBehindIt) {
  // The closed cube-sphere seen from the front: a vertex on the back projects near a front one.
  Scene s;
  s.network = cube_sphere_network(2, FaceScheme::Auto);
  const LiveSurfaces live(s, 8, std::nullopt, "sphere");
  std::vector<SelectionItem> items;
  const PickScene scene = pick_scene(live, items);
  const Camera c = framing(live.draw(), ViewPreset::Front);
  ScenePicker picker;
  const ScenePoints& pts = live.points();
  int pairs = 0;
  for (std::size_t a = 0; a < s.network->vertices.size(); ++a) {
    const Vec3 front = s.network->vertices[a];
    if (front.y > -0.3) continue;
    const Vec2 pa = *project_to_window(c, kRect, front);
    for (std::size_t b = 0; b < s.network->vertices.size(); ++b) {
      const Vec3 back = s.network->vertices[b];
      if (back.y < 0.3) continue;
      const Vec2 pb = *project_to_window(c, kRect, back);
      if (glm::length(pa - pb) > 8) continue;
      // Closer on screen to the back vertex, still the front one.
      const Vec2 cursor = pb + 0.2 * (pa - pb);
      const PickResult r = picker.pick(scene, c, kRect, cursor, {true, false});
      ASSERT_TRUE(r.item);
      EXPECT_EQ(*r.item, SelectionItem::of_point(PointRef::vertex(int(a))));
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 0);
  // Where nothing is in front, a point behind the surface is still picked (the net is drawn
  // over everything, so it is where the user sees it).
  int hidden_picked = 0;
  for (std::size_t i = 0; i < pts.positions.size(); ++i) {
    if (!pts.refs[i] || pts.positions[i].y < 0.5) continue;
    const Vec2 px = *project_to_window(c, kRect, pts.positions[i]);
    const PickResult r = picker.pick(scene, c, kRect, px, {true, false});
    if (r.item && *r.item == SelectionItem::of_point(*pts.refs[i])) ++hidden_picked;
  }
  EXPECT_GT(hidden_picked, 0);
}

TEST(EditorPicking, CastAgreesWithEveryTriangleOnALargeNetwork) {
  Scene s;
  s.network = cube_sphere_network(16, FaceScheme::Auto);  // 1,536 faces
  const LiveSurfaces live(s, 6, std::nullopt, "sphere");
  ASSERT_EQ(live.draw().surfaces.size(), 1536u);
  const Camera c = framing(live.draw());
  ScenePicker picker;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> px(0, kRect.width), py(0, kRect.height);
  for (int k = 0; k < 60; ++k) {
    const Ray ray = window_ray(c, kRect, Vec2(px(rng), py(rng)));
    const auto got = picker.cast(live.draw().surfaces, ray);
    const auto ref = probe_surfaces(live.draw().surfaces, ray);
    ASSERT_EQ(got.has_value(), ref.has_value()) << k;
    if (!got) continue;
    EXPECT_EQ(got->hit.t, ref->distance) << k;
    // The probe at the picker's hit is the reference probe (a tie between two surfaces at a
    // shared border gives the same point and distance).
    const ProbeHit p = probe_at(live.draw().surfaces[got->surface], got->surface, got->hit, ray);
    EXPECT_EQ(p.position, ref->position);
  }
  // Only the surfaces whose boxes the rays entered got a hierarchy, not all 1,536.
  const ScenePicker::Stats st = picker.stats();
  EXPECT_EQ(st.surfaces, 1536u);
  EXPECT_GT(st.hierarchies, 0u);
  EXPECT_LT(st.hierarchies, 1536u / 2);
}

TEST(EditorPicking, AnEditRebuildsOnlyTheChangedSurfaces) {
  Scene s = default_scene();
  LiveSurfaces live(s, 16, std::nullopt, "default");
  ScenePicker picker;
  // Look straight down at vertex 5 (only on the pentagon) after lifting it far up: the picker
  // must see the new surface, not its cached box.
  const Vec3 v5 = s.network->vertices[5];
  set_point_position(s, PointRef::vertex(5), v5 + Vec3(0, 0, 3));
  const Ray down{v5 + Vec3(-0.05, 0, 10), {0, 0, -1}};
  const auto before = picker.cast(live.draw().surfaces, down);
  live.sync(s, 1);
  const auto after = picker.cast(live.draw().surfaces, down);
  const auto ref = probe_surfaces(live.draw().surfaces, down);
  ASSERT_TRUE(after && ref);
  EXPECT_EQ(after->hit.t, ref->distance);
  if (before) {
    EXPECT_LT(after->hit.t, before->hit.t);
  }
}

}  // namespace
}  // namespace pl
