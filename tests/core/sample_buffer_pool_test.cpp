// The pool of dropped sample storage: what it keeps and hands out, and that an evaluator built
// on kept storage (another patch's values in it, NaN included) computes exactly what one on new
// storage does.
#include "core/eval/sample_buffer_pool.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/domain/unit_square.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

constexpr std::size_t kJetBytes = sizeof(SurfaceJet) + sizeof(SurfaceGeometry);

TEST(SampleBufferPool, HandsBackKeptBuffersOfTheSameSizeAndStorageOnly) {
  SampleBufferPool pool;
  SampleBuffers a = pool.take(5000, SampleStorage::Jets);  // nothing kept: new
  ASSERT_EQ(a.jets.size(), 5000u);
  ASSERT_EQ(a.geometry.size(), 5000u);
  EXPECT_TRUE(a.positions.empty());
  const SurfaceJet* jets = a.jets.data();
  const SurfaceGeometry* geometry = a.geometry.data();
  pool.give(std::move(a));
  EXPECT_EQ(pool.kept_count(), 1u);
  EXPECT_EQ(pool.kept_bytes(), 5000 * kJetBytes);
  // Another size or storage: new buffers (the kept ones are still held, so not at their address).
  const SampleBuffers other_size = pool.take(5001, SampleStorage::Jets);
  EXPECT_NE(other_size.jets.data(), jets);
  const SampleBuffers compact = pool.take(5000, SampleStorage::Compact);
  EXPECT_TRUE(compact.jets.empty());
  EXPECT_EQ(compact.positions.size(), 5000u);
  EXPECT_NE(compact.geometry.data(), geometry);
  EXPECT_EQ(pool.kept_count(), 1u);
  // The same size and storage: the kept buffers themselves, no longer kept.
  const SampleBuffers again = pool.take(5000, SampleStorage::Jets);
  EXPECT_EQ(again.jets.data(), jets);
  EXPECT_EQ(again.geometry.data(), geometry);
  EXPECT_EQ(pool.kept_count(), 0u);
  EXPECT_EQ(pool.kept_bytes(), 0u);
}

TEST(SampleBufferPool, KeepsNeitherSmallBuffersNorMoreThanItsBudget) {
  SampleBufferPool pool(5 * 5000 * kJetBytes / 2);  // room for two of 5000 samples
  pool.give(SampleBuffers::fresh(SampleBufferPool::kMinSamples - 1, SampleStorage::Jets));
  EXPECT_EQ(pool.kept_count(), 0u);
  pool.give(SampleBuffers::fresh(15000, SampleStorage::Jets));  // over the whole budget
  EXPECT_EQ(pool.kept_count(), 0u);
  const SurfaceJet* given[3];
  for (const SurfaceJet*& g : given) {
    SampleBuffers b = SampleBuffers::fresh(5000, SampleStorage::Jets);
    g = b.jets.data();
    pool.give(std::move(b));
  }
  EXPECT_EQ(pool.kept_count(), 2u);  // the first given back went for the third
  EXPECT_LE(pool.kept_bytes(), 5 * 5000 * kJetBytes / 2);
  const SampleBuffers x = pool.take(5000, SampleStorage::Jets);
  const SampleBuffers y = pool.take(5000, SampleStorage::Jets);
  EXPECT_TRUE((x.jets.data() == given[1] && y.jets.data() == given[2]) ||
              (x.jets.data() == given[2] && y.jets.data() == given[1]));
}

// Bit for bit: NaN included.
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_same_samples(const PatchEvaluator& a, const PatchEvaluator& b) {
  ASSERT_EQ(a.sample_count(), b.sample_count());
  ASSERT_EQ(a.jets().size(), b.jets().size());
  for (std::size_t i = 0; i < a.sample_count(); ++i) {
    ASSERT_TRUE(same_bits(a.position(i), b.position(i))) << i;
    if (!a.jets().empty()) {
      ASSERT_TRUE(same_bits(a.jets()[i], b.jets()[i])) << i;
    }
    const SurfaceGeometry &g = a.geometry()[i], &h = b.geometry()[i];
    ASSERT_TRUE(same_bits(g.normal, h.normal)) << i;
    ASSERT_TRUE(same_bits(g.gaussian, h.gaussian)) << i;
    ASSERT_TRUE(same_bits(g.mean, h.mean)) << i;
    ASSERT_TRUE(same_bits(g.kmin, h.kmin)) << i;
    ASSERT_TRUE(same_bits(g.kmax, h.kmax)) << i;
    ASSERT_EQ(g.status, h.status) << i;
    ASSERT_EQ(a.finite(i), b.finite(i)) << i;
  }
}

// An evaluator on kept storage overwrites all of it: after one whose patch has a NaN point (every
// sample not finite), another patch's samples equal those of an evaluator on new storage, in
// either storage kind; and dropping it gives the storage back again.
TEST(SampleBufferPool, AnEvaluatorOnKeptStorageEqualsOneOnNewStorage) {
  auto tess = std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(80));
  ASSERT_GE(tess->points.size(), SampleBufferPool::kMinSamples);
  for (const SampleStorage storage : {SampleStorage::Jets, SampleStorage::Compact}) {
    auto pool = std::make_shared<SampleBufferPool>();
    auto broken = std::make_shared<BezierPatch>(3, 4, test::random_points(20, 3));
    broken->set_control_point(6, Vec3(NAN, 0, 0));
    const SurfaceGeometry* storage_address;
    {
      PatchEvaluator first(broken, tess, storage, pool);
      ASSERT_FALSE(first.finite(tess->points.size() / 2));
      storage_address = first.geometry().data();
    }
    EXPECT_EQ(pool->kept_count(), 1u);
    auto patch = std::make_shared<BezierPatch>(3, 4, test::random_points(20, 4));
    {
      PatchEvaluator reused(patch, tess, storage, pool);
      EXPECT_EQ(reused.geometry().data(), storage_address);
      EXPECT_EQ(pool->kept_count(), 0u);
      const PatchEvaluator fresh(std::shared_ptr<Patch>(patch->clone()), tess, storage);
      expect_same_samples(reused, fresh);
      for (std::size_t i = 0; i < reused.sample_count(); ++i) ASSERT_TRUE(reused.finite(i)) << i;
    }
    EXPECT_EQ(pool->kept_count(), 1u);
  }
}

}  // namespace
}  // namespace pl
