#include "render/font.hpp"

#include <stb_truetype.h>  // implementation compiled into Debian's libstb

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pl {

namespace {

// The next code point of UTF-8 text at i (advanced past it); malformed bytes read as U+FFFD.
int next_code_point(std::string_view s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i++);
  if (b < 0x80) return b;
  const int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : -1;
  if (extra < 0 || i + extra > s.size()) return 0xFFFD;
  int c = b & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if ((byte(i) & 0xC0) != 0x80) return 0xFFFD;
    c = (c << 6) | (byte(i++) & 0x3F);
  }
  return c;
}

}  // namespace

struct Font::Face {
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0, cap = 0;  // font units

  float scale(double px) const { return stbtt_ScaleForMappingEmToPixels(&info, float(px)); }
  std::vector<int> glyphs(std::string_view s) const {
    std::vector<int> g;
    for (std::size_t i = 0; i < s.size();)
      g.push_back(stbtt_FindGlyphIndex(&info, next_code_point(s, i)));
    return g;
  }
  // Advance from glyph a to glyph b (b < 0: none follows), in font units.
  int advance(int a, int b) const {
    int adv = 0, lsb = 0;
    stbtt_GetGlyphHMetrics(&info, a, &adv, &lsb);
    return adv + (b >= 0 ? stbtt_GetGlyphKernAdvance(&info, a, b) : 0);
  }
};

const Font& Font::labels() {
  static const Font font(embedded_font_data());
  return font;
}

Font::Font(std::span<const unsigned char> ttf) : face_(std::make_unique<Face>()) {
  const int offset = ttf.empty() ? -1 : stbtt_GetFontOffsetForIndex(ttf.data(), 0);
  if (offset < 0 || !stbtt_InitFont(&face_->info, ttf.data(), offset))
    throw std::runtime_error("the label font is not a TrueType font");
  int gap = 0;
  stbtt_GetFontVMetrics(&face_->info, &face_->ascent, &face_->descent, &gap);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  face_->cap = stbtt_GetCodepointBox(&face_->info, 'H', &x0, &y0, &x1, &y1) ? y1 : face_->ascent;
}

Font::~Font() = default;

double Font::ascent(double px) const {
  return face_->ascent * face_->scale(px);
}

double Font::descent(double px) const {
  return -face_->descent * face_->scale(px);
}

double Font::cap_height(double px) const {
  return face_->cap * face_->scale(px);
}

double Font::width(std::string_view utf8, double px) const {
  const std::vector<int> g = face_->glyphs(utf8);
  long units = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    units += face_->advance(g[i], i + 1 < g.size() ? g[i + 1] : -1);
  return units * double(face_->scale(px));
}

void Font::draw(Image& image, double x, double baseline, std::string_view utf8, double px,
                const Rgb& rgb, float alpha) const {
  const float s = face_->scale(px);
  const std::vector<int> g = face_->glyphs(utf8);
  const double top = std::floor(baseline);
  const float shift_y = static_cast<float>(baseline - top);
  std::vector<unsigned char> bitmap;
  double pen = x;
  for (std::size_t i = 0; i < g.size(); ++i) {
    // Whole pixels plus a sub-pixel shift, so glyph spacing is exact at every size.
    const double left = std::floor(pen);
    const float shift_x = static_cast<float>(pen - left);
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetGlyphBitmapBoxSubpixel(&face_->info, g[i], s, s, shift_x, shift_y, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      bitmap.assign(static_cast<std::size_t>(w) * h, 0);
      stbtt_MakeGlyphBitmapSubpixel(&face_->info, bitmap.data(), w, h, w, s, s, shift_x, shift_y,
                                    g[i]);
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          if (const unsigned char a = bitmap[std::size_t(r) * w + c])
            image.blend(int(left) + x0 + c, int(top) + y0 + r, rgb, alpha * a / 255.0f);
    }
    pen += face_->advance(g[i], i + 1 < g.size() ? g[i + 1] : -1) * double(s);
  }
}

}  // namespace pl
