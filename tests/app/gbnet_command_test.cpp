// `patchlab gbnet`: default control nets and degree elevation of a .gbp from the command line,
// checked against the core functions and the geometry they promise; usage and data errors.
#include <gtest/gtest.h>

#include <random>

#include "cli_test_util.hpp"
#include "core/io/gbp_io.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/elevation.hpp"

namespace pl::test {
namespace {

// A 6-sided net of degree d (quartic by default) whose points lie on the plane
// z = 0.5 x - 0.25 y + 1, interior points lifted off it: the defaults must put them back.
GBPatch lifted_planar_net(int d = 4) {
  const int n = 6;
  std::vector<Vec3> p(GBPatch::point_count(n, d));
  const GBPatch shape(n, d, p);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> r(-0.2, 0.2);
  for (int k = 0; k < shape.layers(); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) {
        const Vec2 a = shape.polygon().vertex(i - 1), b = shape.polygon().vertex(i);
        const Vec2 q = (a + (double(j) / d) * (b - a)) * (1.0 - 0.8 * k / d);
        const double x = 3 * q.x + r(rng), y = 3 * q.y + r(rng);
        p[shape.index(i, j, k)] = {x, y, 0.5 * x - 0.25 * y + 1 + (k > 0 ? 2.0 : 0.0)};
      }
  p[0] = {0, 0, 7};
  return GBPatch(n, d, std::move(p));
}

TEST(GbnetCommand, DefaultsFromTheBoundaryGiveThePlane) {
  TempDir dir;
  const GBPatch in = lifted_planar_net();
  write_gbp(dir / "in.gbp", in);
  const auto r = cli({"gbnet", (dir / "in.gbp").string(), "-o", (dir / "out.gbp").string(),
                      "--defaults", "boundary"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("degree 4"), std::string::npos) << r.out;
  const GBPatch out = read_gbp(dir / "out.gbp");
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Vec3 q = out.control_point(k);
    // |x|, |y| <= 3.2 and the defaults are affine combinations with weights up to about 4 in
    // size (extrapolations), so rounding stays a few ulps of values ~3: 1e-14 is a wide margin.
    EXPECT_NEAR(q.z, 0.5 * q.x - 0.25 * q.y + 1, 1e-14) << k;
    if (gb_ring(6, 4, k) == 0) {
      EXPECT_EQ(q, in.control_point(k)) << k;
    }
  }
  // The same as the library call (the file keeps 17 digits, so exactly).
  const GBPatch direct = gb_default_net(in, 1);
  for (std::size_t k = 0; k < out.size(); ++k)
    EXPECT_EQ(out.control_point(k), direct.control_point(k)) << k;
}

TEST(GbnetCommand, ElevatesKTimesAfterTheDefaults) {
  TempDir dir;
  const GBPatch in = lifted_planar_net();
  write_gbp(dir / "in.gbp", in);
  const auto r = cli({"gbnet", (dir / "in.gbp").string(), "-o", (dir / "out.gbp").string(),
                      "--defaults", "ring1", "--elevate", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const GBPatch out = read_gbp(dir / "out.gbp");
  EXPECT_EQ(out.degree(), 6);
  const GBPatch direct = gb_elevate(gb_elevate(gb_default_net(in, 2)));
  ASSERT_EQ(out.size(), direct.size());
  for (std::size_t k = 0; k < out.size(); ++k)
    EXPECT_EQ(out.control_point(k), direct.control_point(k)) << k;
}

TEST(GbnetCommand, UsageAndDataErrors) {
  TempDir dir;
  write_gbp(dir / "in.gbp", lifted_planar_net());
  const std::string in = (dir / "in.gbp").string(), out = (dir / "out.gbp").string();
  EXPECT_EQ(cli({"gbnet", in, "-o", out}).code, 2);  // nothing to do
  EXPECT_EQ(cli({"gbnet", in, "--defaults", "boundary"}).code, 2);
  EXPECT_EQ(cli({"gbnet", in, "-o", out, "--defaults", "inner"}).code, 2);
  EXPECT_EQ(cli({"gbnet", in, "-o", (dir / "out.json").string(), "--elevate", "1"}).code, 2);
  EXPECT_EQ(cli({"gbnet", in, "-o", out, "--elevate", "0"}).code, 2);
  // Degree 4 + 17 exceeds the format's 20: bad input, named by file with its degree and K,
  // found before any elevation (so no intermediate degree is named), nothing written.
  const auto r = cli({"gbnet", in, "-o", out, "--elevate", "17"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("in.gbp"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("degree 4 cannot be elevated 17 times"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(cli({"gbnet", (dir / "missing.gbp").string(), "-o", out, "--elevate", "1"}).code, 1);
  // Degree 1 has nothing to elevate from (core/patch/gb/elevation.hpp).
  write_gbp(dir / "linear.gbp", lifted_planar_net(1));
  const auto r1 = cli({"gbnet", (dir / "linear.gbp").string(), "-o", out, "--elevate", "1"});
  EXPECT_EQ(r1.code, 1);
  EXPECT_NE(r1.err.find("linear.gbp: degree 1 cannot be elevated"), std::string::npos) << r1.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(GbnetCommand, DegreeTwentyIsNotElevatedAndNothingIsWritten) {
  TempDir dir;
  write_gbp(dir / "top.gbp", lifted_planar_net(GBPatch::kMaxDegree));
  const std::string in = (dir / "top.gbp").string(), out = (dir / "out.gbp").string();
  const auto r = cli({"gbnet", in, "-o", out, "--defaults", "ring1", "--elevate", "1"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("top.gbp"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("degree 20 cannot be elevated 1 times"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  // The defaults alone keep the degree, so they are fine.
  EXPECT_EQ(cli({"gbnet", in, "-o", out, "--defaults", "ring1"}).code, 0);
  EXPECT_EQ(read_gbp(out).degree(), GBPatch::kMaxDegree);
}

TEST(GbnetCommand, AFailedRunLeavesAnExistingOutputAlone) {
  TempDir dir;
  write_gbp(dir / "in.gbp", lifted_planar_net());
  write_gbp(dir / "old.gbp", lifted_planar_net(7));
  const std::string out = (dir / "old.gbp").string(), before = slurp(out);
  ASSERT_FALSE(before.empty());
  const auto r = cli({"gbnet", (dir / "in.gbp").string(), "-o", out, "--elevate", "17"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(slurp(out), before);
  // A usage error and an unreadable input leave it alone too.
  EXPECT_EQ(cli({"gbnet", (dir / "in.gbp").string(), "-o", out, "--defaults", "inner"}).code, 2);
  EXPECT_EQ(cli({"gbnet", (dir / "missing.gbp").string(), "-o", out, "--elevate", "1"}).code, 1);
  EXPECT_EQ(slurp(out), before);
}

}  // namespace
}  // namespace pl::test
