#include "render/image.hpp"

#include <stb_image_write.h>  // implementation compiled into Debian's libstb

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pl {

void Image::blend(int x, int y, const std::array<float, 3>& rgb, float a) {
  if (x < 0 || y < 0 || x >= width || y >= height || a <= 0) return;
  a = std::min(a, 1.0f);
  uint8_t* p = at(x, y);
  const float da = p[3] / 255.0f;
  const float oa = a + da * (1 - a);
  for (int k = 0; k < 3; ++k) {
    const float src = rgb[k] * 255.0f, dst = p[k];
    const float o = oa > 0 ? (src * a + dst * da * (1 - a)) / oa : 0;
    p[k] = static_cast<uint8_t>(std::lround(std::clamp(o, 0.0f, 255.0f)));
  }
  p[3] = static_cast<uint8_t>(std::lround(oa * 255.0f));
}

std::string encode_png(const Image& image) {
  std::string out;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &out, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4))
    throw std::runtime_error("PNG encoding failed");
  return out;
}

}  // namespace pl
