// Every registered patch type (core/patch/patch_types.hpp) against every per-type property: a
// small valid sample of each type is built here, one overload per type, so a type added to the
// registry without a sample does not compile, and each property is checked on it against an
// independent computation (net lines against the points, a flip applied twice, exact sides
// against the surface evaluated on the domain's sides, a codec's write and read).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <type_traits>

#include "core/io/patch_codec.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/network_filling.hpp"
#include "core/patch/control_net_topology.hpp"
#include "core/patch/exact_boundary.hpp"
#include "core/patch/flip_orientation.hpp"
#include "core/patch/patch_types.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(PATCHLAB_SOURCE_DIR) / "assets";

using Sample = std::shared_ptr<const Patch>;

Sample explicit_patch(const std::string& file) {
  return read_scene(kAssets / file).patches.at(0).patch;
}

// The first face of a network asset that the filling makes a T.
template <class T>
Sample face_patch(const std::string& file, std::optional<FaceScheme> scheme) {
  const Scene s = read_scene(kAssets / file);
  const NetworkFilling f =
      fill_network(*s.network, validate_network(*s.network, file), scheme, file);
  for (const FacePatch& fp : f.faces)
    if (patch_as<T>(*fp.patch)) return fp.patch;
  throw std::runtime_error(file + " has no face of type " + T::kType);
}

// One sample per registered type (for_each_sample does not compile for a type without one).
// The classic types: the patch of their asset, assets/classic/<type>.json.
template <OneOf<BSplinePatch, NurbsPatch, InterpolatingPatch, HermitePatch, CoonsNetworkPatch,
                CatmullClarkPatch, PairJoinPatch, GapFillPatch>
              T>
Sample sample(std::type_identity<T>) {
  return explicit_patch(std::string("classic/") + T::kType + ".json");
}
Sample sample(std::type_identity<BezierPatch>) {
  return std::make_shared<BezierPatch>(3, 2, test::random_points(12, 1));
}
Sample sample(std::type_identity<GregoryQuadPatch>) {
  return std::make_shared<GregoryQuadPatch>(test::random_points(GregoryQuadPatch::kPointCount, 2));
}
Sample sample(std::type_identity<GregoryTriPatch>) {
  return std::make_shared<GregoryTriPatch>(test::random_points(GregoryTriPatch::kPointCount, 3));
}
Sample sample(std::type_identity<GBPatch>) {
  return std::make_shared<GBPatch>(5, 3, test::random_points(GBPatch::point_count(5, 3), 4));
}
Sample sample(std::type_identity<GBRibbonPatch>) {
  return face_patch<GBRibbonPatch>("gb-hole-filling.json", FaceScheme::GB);
}
Sample sample(std::type_identity<GBInteriorPatch>) {
  return face_patch<GBInteriorPatch>("gb-interior.json", std::nullopt);
}
Sample sample(std::type_identity<RibbonPatch>) {
  return face_patch<RibbonPatch>("gb-hole-filling.json", FaceScheme::SideBased);
}

// Calls check(patch) on the sample of every registered type, traced with the type's name.
template <class F>
void for_each_sample(F&& check) {
  for_each_patch_type([&]<class T>() {
    const Sample p = sample(std::type_identity<T>{});
    ASSERT_TRUE(patch_as<T>(*p)) << T::kType << ": the sample is a " << p->type();
    SCOPED_TRACE(T::kType);
    check(*p);
  });
}

double diagonal(const Patch& p) {
  Vec3 lo = p.control_point(0), hi = lo;
  for (const Vec3& q : p.control_points()) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

TEST(PatchTypeTable, NamesAreTheTypesOwnAndUnique) {
  const std::vector<std::string> names = patch_type_names();
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for_each_sample([](const Patch& p) {
    // The visit reaches the type's own overload: the name it reports is the patch's type().
    EXPECT_EQ(visit_patch_type(p, []<class T>(const T&) { return std::string(T::kType); }),
              p.type());
  });
}

TEST(PatchTypeTable, AnUnregisteredClassIsAnErrorNotADefault) {
  // A Catmull-Clark face piece is a Patch of its own class, not a registered type.
  const Sample cc = sample(std::type_identity<CatmullClarkPatch>{});
  const auto pieces = cc->surface_pieces();
  ASSERT_FALSE(pieces.empty());
  EXPECT_THROW(control_net_topology(*pieces.front()), std::logic_error);
  EXPECT_EQ(patch_as<CatmullClarkPatch>(*pieces.front()), nullptr);
}

TEST(PatchTypeTable, NetLinesJoinPositionsAndReachEveryOne) {
  for_each_sample([](const Patch& p) {
    const ControlNetTopology t = control_net_topology(p);
    ASSERT_EQ(t.is_vector.size(), p.size());
    std::vector<bool> on_line(p.size(), false);
    for (const auto& s : t.segments) {
      ASSERT_LT(s[0], s[1]);
      ASSERT_LT(s[1], p.size());
      EXPECT_FALSE(t.is_vector[s[0]] || t.is_vector[s[1]]);
      on_line[s[0]] = on_line[s[1]] = true;
    }
    for (const DerivativeArrow& a : t.arrows) {
      ASSERT_LT(a.base, p.size());
      ASSERT_LT(a.vector, p.size());
      EXPECT_FALSE(t.is_vector[a.base]);
      EXPECT_TRUE(t.is_vector[a.vector]);
      EXPECT_GT(a.scale, 0);
    }
    // Every position the net draws is on a line: a net of n positions has at least n / 2 lines.
    std::size_t positions = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
      if (!t.is_vector[k]) {
        ++positions;
        EXPECT_TRUE(on_line[k]) << "point " << k << " is on no net line";
      }
    EXPECT_GT(positions, 0u);
    EXPECT_GE(2 * t.segments.size(), positions);
  });
}

TEST(PatchTypeTable, FlippingTwiceGivesThePointsBackOrIsRefusedByName) {
  for_each_sample([](const Patch& p) {
    if (!can_flip_orientation(p)) {
      try {
        flipped_orientation(p);
        ADD_FAILURE() << "a type that cannot flip was flipped";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(p.type()), std::string::npos) << e.what();
      }
      return;
    }
    const FlippedPatch once = flipped_orientation(p);
    EXPECT_EQ(once.patch->type(), p.type());
    std::vector<std::size_t> sorted = once.old_index;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k);
    EXPECT_EQ(flipped_orientation(*once.patch).patch->control_points(), p.control_points());
  });
}

TEST(PatchTypeTable, ExactBoundaryCurvesAreTheSurfaceOnItsSides) {
  std::set<std::string> exact;
  for_each_sample([&](const Patch& p) {
    if (!boundary_curves_are_exact(p)) return;
    exact.insert(p.type());
    const std::vector<BezierCurve> curves = p.boundary_curves();
    ASSERT_EQ(int(curves.size()), p.domain().side_count());
    const double tol = 1e-10 * std::max(diagonal(p), 1.0);
    for (int s = 0; s < p.domain().side_count(); ++s)
      for (int i = 0; i <= 10; ++i) {
        const double t = i / 10.0;
        const Vec3 c = curves[s].point(t);
        // The surface itself on the domain side (evaluate, independent of boundary_curves) and
        // the side's defining curve.
        EXPECT_LT(glm::length(c - p.evaluate(p.domain().side_point(s, t)).p), tol)
            << "side " << s << " t " << t;
        EXPECT_LT(glm::length(c - p.boundary_point(s, t)), tol) << "side " << s << " t " << t;
      }
  });
  // CAD export takes these sides as exact edges: the network GB faces with interior control too.
  EXPECT_TRUE(exact.count(GBInteriorPatch::kType));
  EXPECT_TRUE(exact.count(GBRibbonPatch::kType));
}

// Types a scene file never holds as an explicit patch: a GB face with interior control is written
// as its network face's offsets (docs/scene-format.md).
bool network_only(const std::string& type) {
  return type == GBInteriorPatch::kType;
}

TEST(PatchTypeTable, CodecsRoundTripEveryExplicitType) {
  const std::vector<std::string> names = patch_type_names();
  for (const PatchCodec& c : patch_codecs())
    EXPECT_NE(std::find(names.begin(), names.end(), c.type), names.end())
        << "codec of an unregistered type " << c.type;
  for_each_sample([](const Patch& p) {
    const PatchCodec* codec = find_patch_codec(p.type());
    if (network_only(p.type())) {
      EXPECT_EQ(codec, nullptr);
      return;
    }
    ASSERT_NE(codec, nullptr) << "no codec";
    Scene scene;
    scene.patches.push_back({"sample", p.clone()});
    const Scene back = parse_scene(scene_to_json(scene), "round trip");
    ASSERT_EQ(back.patches.size(), 1u);
    const Patch& q = *back.patches[0].patch;
    EXPECT_EQ(q.type(), p.type());
    EXPECT_EQ(q.control_points(), p.control_points());
    EXPECT_EQ(q.domain().side_count(), p.domain().side_count());
    // The same surface, not just the same points (knots, weights, options written too).
    const Vec2 inside = p.domain().interior_point();
    for (const Vec2& x : {inside, 0.7 * inside + 0.3 * p.domain().side_point(0, 0.4)})
      EXPECT_EQ(q.evaluate(x).p, p.evaluate(x).p);
  });
}

}  // namespace
}  // namespace pl
