// `patchlab sample`: the written network reads back as the generator's network; usage errors.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "core/io/scene_io.hpp"
#include "core/network/sample_networks.hpp"

namespace pl::test {
namespace {

TEST(SampleCommand, CubeSphereReadsBackExactly) {
  TempDir dir;
  const auto r = cli({"sample", "cube-sphere", "--cells", "2", "--scheme", "gb", "-o",
                      (dir / "s.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const Scene s = read_scene(dir / "s.json");
  const Network expected = cube_sphere_network(2, FaceScheme::GB);
  ASSERT_TRUE(s.network);
  ASSERT_EQ(s.network->faces.size(), 24u);
  ASSERT_EQ(s.network->vertices, expected.vertices);
  for (std::size_t e = 0; e < expected.edges.size(); ++e) {
    EXPECT_EQ(s.network->edges[e].v, expected.edges[e].v);
    EXPECT_EQ(s.network->edges[e].handles, expected.edges[e].handles);
  }
  for (const NetworkFace& f : s.network->faces) EXPECT_EQ(f.scheme, FaceScheme::GB);
}

TEST(SampleCommand, UsageErrors) {
  TempDir dir;
  const std::string out = (dir / "s.json").string();
  EXPECT_EQ(cli({"sample", "teapot", "-o", out}).code, 2);
  EXPECT_EQ(cli({"sample", "cube-sphere"}).code, 2);
  EXPECT_EQ(cli({"sample", "cube-sphere", "-o", (dir / "s.obj").string()}).code, 2);
  EXPECT_EQ(cli({"sample", "cube-sphere", "--cells", "0", "-o", out}).code, 2);
  EXPECT_EQ(cli({"sample", "cube-sphere", "--scheme", "coons", "-o", out}).code, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace pl::test
