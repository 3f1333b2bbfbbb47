// The core's parallel loops (core/base/parallel_for.hpp): every index once, in tasks of the
// grain, really on several threads, exceptions carried to the caller; and the evaluator's results
// the same bit for bit on one thread and on many, whatever the grains.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "core/base/parallel_for.hpp"
#include "core/domain/convex_polygon.hpp"
#include "core/domain/unit_square.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "test_util.hpp"

namespace pl {
namespace {

TEST(ParallelChunks, CoversEveryIndexOnceInTasksOfTheGrain) {
  for (const std::size_t n : {0, 1, 7, 64, 1000, 4099}) {
    for (const std::size_t grain : {1, 3, 64, 5000}) {
      std::vector<std::atomic<int>> hits(n);
      std::atomic<bool> too_big = false;
      parallel_chunks(n, grain, [&](std::size_t b, std::size_t e) {
        if (e - b > grain || b >= e) too_big = true;
        for (std::size_t i = b; i < e; ++i) ++hits[i];
      });
      EXPECT_FALSE(too_big) << "n " << n << " grain " << grain;
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << "n " << n << " index " << i;
    }
  }
}

TEST(ParallelChunks, RunsTasksOnSeveralThreadsAtOnce) {
  ASSERT_GE(oneapi::tbb::info::default_concurrency(), 2) << "a machine of one core cannot tell";
  // Two tasks that each wait for the other to have started: only two threads running at once
  // finish them (a one-thread run would wait out the deadline in the first task).
  std::atomic<int> started = 0;
  std::mutex m;
  std::set<std::thread::id> threads;
  parallel_chunks(2, 1, [&](std::size_t, std::size_t) {
    {
      const std::lock_guard lock(m);
      threads.insert(std::this_thread::get_id());
    }
    ++started;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (started < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
  });
  EXPECT_EQ(started, 2);
  EXPECT_EQ(threads.size(), 2u);
}

TEST(ParallelChunks, CarriesTheFirstExceptionToTheCaller) {
  try {
    parallel_chunks(1000, 10, [&](std::size_t b, std::size_t e) {
      if (b <= 500 && 500 < e) throw std::runtime_error("sample 500 failed");
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "sample 500 failed");
  }
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

// What an evaluator holds after a script of edits: a drag of one point, batched moves of several
// (twice, so the second one uses their columns), then a full evaluation of a moved patch.
struct Run {
  std::vector<SurfaceJet> jets;
  std::vector<Vec3> positions;
  std::vector<SurfaceGeometry> geometry;
  std::vector<bool> finite;
};

Run run_script(const Patch& patch, std::shared_ptr<const Tessellation> tess, SampleStorage storage,
               const PatchEvaluator::Grains* grains) {
  PatchEvaluator ev(std::shared_ptr<Patch>(patch.clone()), tess, storage);
  if (grains) {
    ev.set_grains(*grains);
    ev.evaluate_all();
  }
  const std::size_t n = patch.size();
  const std::size_t a = n / 2, b = n / 3, c = n - 1;
  for (int step = 1; step <= 4; ++step)
    ev.move_control_point(a, patch.control_point(a) + Vec3(0.01 * step, -0.02, 0.03 * step));
  for (int step = 1; step <= 2; ++step) {
    const std::vector<PatchEvaluator::PointMove> moves{
        {a, patch.control_point(a) + Vec3(0.1, 0.0, -0.05 * step)},
        {b, patch.control_point(b) + Vec3(0.0, 0.07 * step, 0.02)},
        {c, patch.control_point(c) + Vec3(-0.03, 0.0, 0.04 * step)}};
    ev.move_control_points(moves);
  }
  Run r;
  r.jets = ev.jets();
  r.geometry = ev.geometry();
  for (std::size_t i = 0; i < ev.sample_count(); ++i) {
    r.positions.push_back(ev.position(i));
    r.finite.push_back(ev.finite(i));
  }
  return r;
}

void expect_same_bits(const Run& x, const Run& y, const char* what) {
  ASSERT_EQ(x.geometry.size(), y.geometry.size()) << what;
  ASSERT_EQ(x.jets.size(), y.jets.size()) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < x.geometry.size(); ++i) {
    const SurfaceGeometry &g = x.geometry[i], &h = y.geometry[i];
    const bool same = same_bits(x.positions[i], y.positions[i]) && same_bits(g.normal, h.normal) &&
                      same_bits(g.gaussian, h.gaussian) && same_bits(g.mean, h.mean) &&
                      same_bits(g.kmin, h.kmin) && same_bits(g.kmax, h.kmax) &&
                      g.status == h.status && x.finite[i] == y.finite[i];
    differ += !same;
  }
  for (std::size_t i = 0; i < x.jets.size(); ++i) {
    const SurfaceJet &j = x.jets[i], &k = y.jets[i];
    differ += !(same_bits(j.p, k.p) && same_bits(j.su, k.su) && same_bits(j.sv, k.sv) &&
                same_bits(j.suu, k.suu) && same_bits(j.suv, k.suv) && same_bits(j.svv, k.svv));
  }
  EXPECT_EQ(differ, 0u) << what << ": samples whose bits differ";
}

// One thread with the default grains, the default threads with the default grains, and the
// default threads with small odd grains (every task a different cut of the SIMD lanes and of the
// evaluation chunks): the same bits.
void expect_thread_independent(const Patch& patch, std::shared_ptr<const Tessellation> tess) {
  ASSERT_GT(tess->points.size(), 20000u) << "enough samples for many tasks of the default grains";
  const PatchEvaluator::Grains odd{333, 101, 37};
  for (const SampleStorage storage : {SampleStorage::Jets, SampleStorage::Compact}) {
    const char* what = storage == SampleStorage::Jets ? "jets" : "compact";
    Run one;
    {
      const oneapi::tbb::global_control single(oneapi::tbb::global_control::max_allowed_parallelism,
                                               1);
      one = run_script(patch, tess, storage, nullptr);
    }
    expect_same_bits(one, run_script(patch, tess, storage, nullptr), what);
    expect_same_bits(one, run_script(patch, tess, storage, &odd), what);
  }
}

TEST(ParallelDeterminism, BezierPatchSameBitsOnOneThreadAndMany) {
  const BezierPatch patch(3, 4, test::random_points(20, 5));
  expect_thread_independent(
      patch, std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(180)));
}

TEST(ParallelDeterminism, GBPatchSameBitsOnOneThreadAndMany) {
  // The batched SIMD path, five sides of degree 5, with singular corners.
  const GBPatch patch(5, 5, test::random_points(GBPatch::point_count(5, 5), 11));
  expect_thread_independent(
      patch, std::make_shared<const Tessellation>(ConvexPolygonDomain::regular(5).tessellate(110)));
}

TEST(ParallelDeterminism, BSplinePatchSparseColumnsSameBitsOnOneThreadAndMany) {
  // Local support: sparse influence columns, updated through their sample index.
  std::vector<double> knots{0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};
  const BSplinePatch patch(3, 3, knots, knots, 8, 8, test::random_points(64, 23));
  expect_thread_independent(
      patch, std::make_shared<const Tessellation>(UnitSquareDomain().tessellate(180)));
}

}  // namespace
}  // namespace pl
