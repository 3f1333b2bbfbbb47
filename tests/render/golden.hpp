// Golden images: renders compared pixel by pixel with tests/data/golden/NAME.png. Regenerate after
// an intended visual change with
//   PATCHLAB_UPDATE_GOLDENS=1 build/tests/patchlab_render_tests --gtest_filter='*Golden*'
// and look at the new PNGs before committing them.
#pragma once

#include <gtest/gtest.h>
#include <stb_image.h>  // implementation compiled into Debian's libstb

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "render/image.hpp"

namespace pl::test {

// Per channel, in 8-bit levels: absorbs rasteriser rounding differences between Mesa versions
// on smooth shading and colour ramps.
inline constexpr int kChannelTolerance = 8;
// Pixels allowed beyond that: antialiased silhouettes and line edges may move by a sample.
inline constexpr double kOutlierFraction = 0.003;

inline const std::filesystem::path& golden_dir() {
  static const std::filesystem::path dir =
      std::filesystem::path(PATCHLAB_SOURCE_DIR) / "tests" / "data" / "golden";
  return dir;
}

inline void compare_with_golden(const std::string& name, const Image& image) {
  const auto path = golden_dir() / (name + ".png");
  const char* update = std::getenv("PATCHLAB_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    std::filesystem::create_directories(golden_dir());
    std::ofstream(path, std::ios::binary) << encode_png(image);
    std::cout << "updated " << path << "\n";
    return;
  }
  int w = 0, h = 0, channels = 0;
  stbi_uc* golden = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
  ASSERT_NE(golden, nullptr) << "missing golden " << path
                             << " (create it with PATCHLAB_UPDATE_GOLDENS=1)";
  ASSERT_EQ(w, image.width);
  ASSERT_EQ(h, image.height);
  int outliers = 0, worst = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    int d = 0;
    for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(int(golden[i + k]) - image.rgba[i + k]));
    worst = std::max(worst, d);
    if (d > kChannelTolerance) ++outliers;
  }
  stbi_image_free(golden);
  const int allowed = static_cast<int>(kOutlierFraction * w * h);
  if (outliers > allowed) {
    const auto actual = std::filesystem::temp_directory_path() / (name + ".actual.png");
    std::ofstream(actual, std::ios::binary) << encode_png(image);
    ADD_FAILURE() << name << ": " << outliers << " pixels differ by more than " << kChannelTolerance
                  << " levels (allowed " << allowed << ", worst " << worst
                  << "); this render is in " << actual;
  }
}

// The w x h block of `image` at (x, y).
inline Image crop(const Image& image, int x, int y, int w, int h) {
  Image out(w, h);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) std::copy_n(image.at(x + c, y + r), 4, out.at(c, r));
  return out;
}

}  // namespace pl::test
