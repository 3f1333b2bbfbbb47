// `patchlab render`: wrong usage exits 2 before any work, bad files exit 1 naming the file, and
// a real render writes a PNG of the requested size (skipped when no GL context can be made).
#include <gtest/gtest.h>
#include <stb_image.h>  // implementation compiled into Debian's libstb

#include "app/cli_test_util.hpp"
#include "render/egl_context.hpp"

namespace pl::test {
namespace {

const std::string kSaddle = std::string(PATCHLAB_SOURCE_DIR) + "/assets/bezier-saddle.json";

bool have_gl(std::string& why) {
  try {
    EglContext context;
    return true;
  } catch (const GlContextError& e) {
    why = e.what();
    return false;
  }
}

TEST(RenderCommand, WrongUsageExits2) {
  TempDir dir;
  const std::string out = (dir / "out.png").string();
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", kSaddle},                                        // no -o
           {"render", kSaddle, "-o", (dir / "out.jpg").string()},      // not a PNG
           {"render", kSaddle, "-o", out, "--size", "0x10"},           // empty image
           {"render", kSaddle, "-o", out, "--size", "5000x100"},       // beyond 4096
           {"render", kSaddle, "-o", out, "--size", "800"},            // not WxH
           {"render", kSaddle, "-o", out, "--mode", "mean+gaussian"},  // two base modes
           {"render", kSaddle, "-o", out, "--mode", "wireframe"},      // unknown mode
           {"render", kSaddle, "-o", out, "--mode", "shaded+comb"},    // combs misspelt
           {"render", kSaddle, "-o", out, "--range", "0:1"},           // not around zero
           {"render", kSaddle, "-o", out, "--compare", "--scheme", "gb"},
       }) {
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, kExitUsage) << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find("usage:"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(RenderCommand, BadInputExits1NamingTheFile) {
  TempDir dir;
  const auto broken = dir.file("broken.json", R"({"patchlab": 1, "patches": [{"type": "x"}]})");
  const auto camera = dir.file("camera.json", R"({"pitch_deg": 120})");
  const std::string out = (dir / "out.png").string();
  CliResult r = cli({"render", broken.string(), "-o", out});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("broken.json"), std::string::npos) << r.err;
  r = cli({"render", kSaddle, "-o", out, "--view", camera.string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("camera.json: pitch_deg"), std::string::npos) << r.err;
  r = cli({"render", kSaddle, "-o", out, "--compare"});  // no network to fill two ways
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderCommand, WritesAPngOfTheRequestedSize) {
  std::string why;
  if (!have_gl(why)) GTEST_SKIP() << "no OpenGL: " << why;
  TempDir dir;
  const auto camera = dir.file("camera.json", R"({"yaw_deg": 30, "pitch_deg": 50,
      "projection": "orthographic"})");
  for (const std::vector<std::string>& extra : std::vector<std::vector<std::string>>{
           {"--mode", "mean+isophotes+control-net", "--view", "top"},
           {"--mode", "zebra", "--transparent", "--view", camera.string()},
       }) {
    const auto out = dir / "out.png";
    std::vector<std::string> args{"render", kSaddle,   "-o",        out.string(),
                                  "--size", "200x150", "--density", "8"};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = cli(args);
    ASSERT_EQ(r.code, kExitOk) << r.err;
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load(out.string().c_str(), &w, &h, &n, 4);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, 200);
    EXPECT_EQ(h, 150);
    // Something was drawn: a good share of pixels differ clearly from the top-left corner
    // (backdrop or clear colour).
    int drawn = 0;
    for (int i = 0; i < w * h; ++i) {
      int diff = 0;
      for (int k = 0; k < 4; ++k) diff += std::abs(int(pixels[i * 4 + k]) - int(pixels[k]));
      if (diff > 30) ++drawn;
    }
    EXPECT_GT(drawn, w * h / 10) << extra[1];
    if (extra[2] == "--transparent") {
      EXPECT_EQ(pixels[3], 0);
    }
    stbi_image_free(pixels);
  }
}

// Pixels of the combs' teal (green well above red, not below blue): no other overlay, surface
// shading or backdrop has that hue.
int teal_pixels(const std::filesystem::path& png) {
  int w = 0, h = 0, n = 0;
  stbi_uc* p = stbi_load(png.string().c_str(), &w, &h, &n, 4);
  EXPECT_NE(p, nullptr) << png;
  if (!p) return -1;
  int count = 0;
  for (int i = 0; i < w * h; ++i)
    if (p[4 * i + 1] > p[4 * i] + 60 && p[4 * i + 1] >= p[4 * i + 2]) ++count;
  stbi_image_free(p);
  return count;
}

TEST(RenderCommand, CombsAddTealTeethOnNetworkCurvesAndBorders) {
  std::string why;
  if (!have_gl(why)) GTEST_SKIP() << "no OpenGL: " << why;
  TempDir dir;
  const std::string network = std::string(PATCHLAB_SOURCE_DIR) + "/assets/default.json";
  auto render = [&](const std::string& file, const std::string& mode,
                    std::vector<std::string> extra = {}) {
    const auto out = dir / "out.png";
    std::vector<std::string> args{"render",  file,        "-o", out.string(), "--size",
                                  "300x225", "--density", "8",  "--mode",     mode};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult r = cli(args);
    EXPECT_EQ(r.code, kExitOk) << mode << ": " << r.err;
    return teal_pixels(out);
  };
  EXPECT_EQ(render(network, "shaded+network+borders"), 0);
  EXPECT_GT(render(network, "shaded+network+combs"), 500);
  EXPECT_GT(render(network, "combs"), 500);  // alone: on the network curves
  EXPECT_GT(render(network, "mean+borders+combs", {"--compare"}), 1000);
  EXPECT_GT(render(kSaddle, "shaded+borders+combs"), 200);  // explicit patch: borders
}

// Teal (comb) pixels within `margin` pixels of the image's edge.
int teal_pixels_at_the_edge(const std::filesystem::path& png, int margin) {
  int w = 0, h = 0, n = 0;
  stbi_uc* p = stbi_load(png.string().c_str(), &w, &h, &n, 4);
  EXPECT_NE(p, nullptr) << png;
  if (!p) return -1;
  int count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x >= margin && y >= margin && x < w - margin && y < h - margin) continue;
      const stbi_uc* q = p + 4 * (y * w + x);
      if (q[1] > q[0] + 60 && q[1] >= q[2]) ++count;
    }
  stbi_image_free(p);
  return count;
}

// The combs of free curves stand out of them by up to three reference lengths; the default
// view and the preset views frame their tips, so no comb runs into the picture's edge (the
// hyperbola's comb of the conics did, and the top B-spline's comb in the top view).
TEST(RenderCommand, CombsOfFreeCurvesAreNotCutByTheFrame) {
  std::string why;
  if (!have_gl(why)) GTEST_SKIP() << "no OpenGL: " << why;
  TempDir dir;
  const std::string curves = std::string(PATCHLAB_SOURCE_DIR) + "/assets/curves/";
  for (const auto& [file, view] :
       std::vector<std::pair<std::string, std::string>>{{"nurbs-circle-and-conics.json", ""},
                                                        {"bspline-knot-multiplicity.json", ""},
                                                        {"bspline-knot-multiplicity.json", "top"},
                                                        {"joints-g0-g1-g2.json", "top"}}) {
    const auto out = dir / "out.png";
    std::vector<std::string> args{"render", curves + file, "-o",     out.string(),
                                  "--size", "400x260",     "--mode", "combs"};
    if (!view.empty()) args.insert(args.end(), {"--view", view});
    const CliResult r = cli(args);
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_GT(teal_pixels(out), 1000) << file << " " << view;
    EXPECT_EQ(teal_pixels_at_the_edge(out, 3), 0) << file << " " << view;
  }
}

}  // namespace
}  // namespace pl::test
