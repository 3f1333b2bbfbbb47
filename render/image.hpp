// An RGBA8 image in memory, top row first, and its PNG encoding. GL-free.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pl {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4, straight (not premultiplied) alpha

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  uint8_t* at(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const uint8_t* at(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
  // Alpha-blends an sRGB colour with coverage `a` (0..1) over pixel (x, y); clipped.
  void blend(int x, int y, const std::array<float, 3>& rgb, float a);
};

// PNG file content (stb_image_write into memory); throws std::runtime_error if encoding fails.
std::string encode_png(const Image& image);

}  // namespace pl
