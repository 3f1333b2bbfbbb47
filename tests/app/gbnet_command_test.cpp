// `patchlab gbnet`: default control nets and degree elevation of a .gbp from the command line,
// checked against the core functions and the geometry they promise; usage and data errors.
#include <gtest/gtest.h>

#include <random>

#include "cli_test_util.hpp"
#include "core/io/gbp_io.hpp"
#include "core/patch/gb_default_net.hpp"
#include "core/patch/gb_elevation.hpp"

namespace pl::test {
namespace {

// A 6-sided quartic net whose points lie on the plane z = 0.5 x - 0.25 y + 1, interior points
// lifted off it: the defaults must put them back.
GBPatch lifted_planar_net() {
  const int n = 6, d = 4;
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
    EXPECT_NEAR(q.z, 0.5 * q.x - 0.25 * q.y + 1, 1e-12 * 10) << k;
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
  // Degree 4 + 17 exceeds the format's 20: bad input, named by file, nothing written.
  const auto r = cli({"gbnet", in, "-o", out, "--elevate", "17"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("in.gbp"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(cli({"gbnet", (dir / "missing.gbp").string(), "-o", out, "--elevate", "1"}).code, 1);
}

}  // namespace
}  // namespace pl::test
