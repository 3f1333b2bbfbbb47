// `patchlab render cagd86.gbp -o x.png --mode shaded` in its default view shows the patch's
// front side filling a good part of the frame; the iso view of the same file (which used to be
// the default) sees its back. Measured on the PNGs the command writes.
#include <gtest/gtest.h>
#include <stb_image.h>  // implementation compiled into Debian's libstb

#include <cstdio>
#include <filesystem>

#include "app/cli_test_util.hpp"
#include "render_test_util.hpp"

namespace pl::test {
namespace {

const std::string kCagd86 = std::string(PATCHLAB_TEST_DATA_DIR) + "/gb/cagd86.gbp";

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
};

Png render_png(const TempDir& dir, const std::string& name, std::vector<std::string> extra) {
  const std::string out = (dir / name).string();
  std::vector<std::string> args{"render", kCagd86, "-o", out, "--mode", "shaded"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CliResult r = cli(args);
  EXPECT_EQ(r.code, kExitOk) << r.err;
  Png png;
  int n = 0;
  stbi_uc* pixels = stbi_load(out.c_str(), &png.width, &png.height, &n, 4);
  if (!pixels) {
    ADD_FAILURE() << "cannot read " << out;
    return png;
  }
  png.rgba.assign(pixels, pixels + std::size_t(png.width) * png.height * 4);
  stbi_image_free(pixels);
  return png;
}

// The share of the frame the patch covers (the opaque pixels of the transparent render) and the
// share of those that show the back-face colour in the plain render (terracotta: red well above
// blue; the front and the background are cool greys with blue at least red).
struct Coverage {
  double covered = 0, back = 0;
};

Coverage coverage(const Png& plain, const Png& transparent) {
  EXPECT_EQ(plain.width, transparent.width);
  EXPECT_EQ(plain.height, transparent.height);
  long covered = 0, back = 0;
  for (std::size_t i = 0; i + 3 < plain.rgba.size() && i + 3 < transparent.rgba.size(); i += 4) {
    if (transparent.rgba[i + 3] < 255) continue;
    ++covered;
    back += int(plain.rgba[i]) - int(plain.rgba[i + 2]) > 30;
  }
  const double pixels = double(plain.width) * plain.height;
  return {pixels > 0 ? covered / pixels : 0.0, covered ? double(back) / covered : 0.0};
}

TEST(Cagd86Render, DefaultViewShowsTheFrontFillingTheFrame) {
  PATCHLAB_REQUIRE_GL();
  ASSERT_TRUE(std::filesystem::exists(kCagd86)) << kCagd86;
  TempDir dir;
  const Coverage seen =
      coverage(render_png(dir, "x.png", {}), render_png(dir, "x-alpha.png", {"--transparent"}));
  const Coverage iso =
      coverage(render_png(dir, "iso.png", {"--view", "iso"}),
               render_png(dir, "iso-alpha.png", {"--view", "iso", "--transparent"}));
  std::printf(
      "cagd86: default view covers %.2f of the frame (back %.3f); iso view %.2f (back %.3f)\n",
      seen.covered, seen.back, iso.covered, iso.back);
  // The measure tells the sides apart: the iso view sees the back almost everywhere.
  EXPECT_GT(iso.back, 0.9);
  EXPECT_LT(seen.back, 0.01);
  EXPECT_GT(seen.covered, 0.3);
}

}  // namespace
}  // namespace pl::test
