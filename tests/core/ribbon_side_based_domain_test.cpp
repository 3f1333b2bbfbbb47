// The side-based scheme's default domain, built from the curves (core/patch/transfinite/
// angular_domain.hpp): it reproduces the domain the research library built for the reference
// samples (their vertex lines), so a side-based face written without a domain is the library's
// surface; and it follows the curves when a curve point moves.
#include <gtest/gtest.h>

#include "core/eval/patch_evaluator.hpp"
#include "core/patch/transfinite/angular_domain.hpp"
#include "ribbon_test_util.hpp"

namespace pl {
namespace {

using transfinite::RibbonScheme;

TEST(RibbonSideBasedDomain, IsTheLibrarysDomainOfTheReferenceFaces) {
  for (int n = 3; n <= 6; ++n) {
    const auto samples = test::read_scheme_samples(
        test::scheme_reference_dir() / ("side-based-face" + std::to_string(n) + ".samples.txt"));
    ASSERT_EQ(samples.size(), std::size_t(12 * n + 301));
    const RibbonPatch p(RibbonScheme::SideBased, test::reference_face(n));
    ASSERT_TRUE(p.default_domain());
    double worst = 0;
    for (int i = 0; i < n; ++i)
      worst = std::max(worst, glm::length(p.polygon().vertex(i) - samples[std::size_t(i)].x));
    // The library's own derivative evaluation rounds differently: its README measured 1.6e-15.
    EXPECT_LT(worst, 1e-14) << "face" << n;
    // The library's centre (the n-th line) of the same vertices.
    std::vector<Vec2> v;
    for (int i = 0; i < n; ++i) v.push_back(samples[std::size_t(i)].x);
    EXPECT_LT(glm::length(transfinite::angular_domain_centre(v) - samples[std::size_t(n)].x), 1e-15)
        << "face" << n;
    std::printf("[ angular ] face%d domain vertices within %.3g of the library's\n", n, worst);
  }
}

TEST(RibbonSideBasedDomain, AFaceWithoutADomainIsTheLibrarysSurface) {
  // The default patch at every sample point (its domain vertices rounding away from the file's):
  // the library's points to 1e-12 of the face's size.
  for (int n = 3; n <= 6; ++n) {
    const auto sides = test::reference_face(n);
    const auto samples = test::read_scheme_samples(
        test::scheme_reference_dir() / ("side-based-face" + std::to_string(n) + ".samples.txt"));
    const RibbonPatch p(RibbonScheme::SideBased, sides);
    const double size = test::points_diagonal(sides);
    double worst = 0;
    for (const auto& s : samples) worst = std::max(worst, glm::length(p.evaluate(s.x).p - s.p));
    EXPECT_LT(worst / size, 1e-12) << "face" << n;
    std::printf("[ angular ] side-based face%d without a domain: max error %.3g relative\n", n,
                worst / size);
  }
}

TEST(RibbonSideBasedDomain, FollowsAMovedCurvePointAndOnlyThen) {
  const auto sides = test::reference_face(5);
  RibbonPatch p(RibbonScheme::SideBased, sides);
  const std::string before = p.domain().key();
  // A cross-derivative vector: the domain stays.
  std::size_t cross = 0;
  while (p.kind(cross) != ControlPointKind::Inner) ++cross;
  p.set_control_point(cross, p.control_point(cross) + Vec3(0.3, 0.1, -0.2));
  EXPECT_EQ(p.domain().key(), before);
  // A curve point (an inner one of side 2): the domain is the one a fresh patch of the moved
  // curves builds, and so is the surface.
  std::vector<RibbonSide> moved = p.sides();
  moved[2].curve.points[1] += Vec3(1.5, -0.7, 0.4);
  std::size_t k = 0;
  for (int i = 0; i < 2; ++i)
    k += sides[std::size_t(i)].curve.points.size() + sides[std::size_t(i)].cross.points.size();
  p.set_control_point(k + 1, moved[2].curve.points[1]);
  RibbonPatchOptions unchecked;  // the moved tangent no longer matches side 1's cross derivative
  unchecked.check_corners = false;
  const RibbonPatch fresh(RibbonScheme::SideBased, moved, unchecked);
  EXPECT_NE(p.domain().key(), before);
  EXPECT_EQ(p.domain().key(), fresh.domain().key());
  for (int i = 0; i <= 10; ++i) {
    const Vec2 x =
        0.1 * i * fresh.polygon().vertex(1) + (1 - 0.1 * i) * fresh.polygon().interior_point();
    EXPECT_LT(glm::length(p.evaluate(x).p - fresh.evaluate(x).p), 1e-12);
  }
  // The other schemes keep the regular n-gon whatever the curves.
  const RibbonPatch cb(RibbonScheme::CornerBased, moved, unchecked);
  EXPECT_EQ(cb.domain().key(), ConvexPolygonDomain::regular(5).key());
}

TEST(RibbonSideBasedDomain, AnEvaluatorMovingACurvePointFollowsTheNewDomain) {
  // The surface is not linear in a curve point when the domain follows the curves: an evaluator
  // asked to move one evaluates afresh on the new domain's tessellation (both storages), and
  // equals a fresh evaluator of the moved patch.
  for (SampleStorage storage : {SampleStorage::Jets, SampleStorage::Compact}) {
    auto patch = std::make_shared<RibbonPatch>(RibbonScheme::SideBased, test::reference_face(5));
    const Domain& d0 = patch->domain();
    PatchEvaluator ev(patch, std::make_shared<const Tessellation>(d0.tessellate(12)), storage);
    std::size_t k = 0;
    while (patch->kind(k) != ControlPointKind::Boundary || k == 0) ++k;  // an inner curve point
    const Vec3 to = patch->control_point(k) + Vec3(1.2, -0.6, 0.5);
    ev.move_control_point(k, to);
    auto moved = std::shared_ptr<RibbonPatch>(static_cast<RibbonPatch*>(patch->clone().release()));
    const PatchEvaluator fresh(
        moved, std::make_shared<const Tessellation>(moved->domain().tessellate(12)), storage);
    ASSERT_EQ(ev.sample_count(), fresh.sample_count());
    for (std::size_t i = 0; i < ev.sample_count(); ++i) {
      EXPECT_EQ(ev.tessellation().points[i], fresh.tessellation().points[i]);
      EXPECT_LT(glm::length(ev.position(i) - fresh.position(i)), 1e-12);
    }
  }
}

}  // namespace
}  // namespace pl
