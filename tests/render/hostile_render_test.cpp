// `patchlab render` on hostile input: a scene whose evaluation overflows is refused before any
// drawing, naming the patch and the domain parameter, and no PNG is written (the check runs
// before a GL context is made, so this needs none).
#include <gtest/gtest.h>

#include "app/cli_test_util.hpp"

namespace pl::test {
namespace {

TEST(HostileRender, NonFiniteSamplesAreRefusedNamingPatchAndParameter) {
  TempDir dir;
  // The G2 pair-join construction squares lengths: at scale 1e150 its points overflow.
  const auto scene = dir.file(
      "pj.json",
      scaled(nlohmann::json::parse(slurp(PATCHLAB_SOURCE_DIR "/assets/classic/pair-join.json")),
             1e150)
          .dump());
  const auto out = dir / "pj.png";
  const CliResult r = cli({"render", scene.string(), "-o", out.string(), "--size", "64x48"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find(scene.string() + ": patch \"g2-pair\" at (u, v) = ("), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace pl::test
