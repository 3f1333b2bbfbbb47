// The label font: DejaVu Sans (Debian's fonts-dejavu-core) compiled into the binary at build time
// (render/embed_font.cmake), rasterised by stb_truetype (Debian's libstb) at any size with
// sub-pixel placement, so text burned into exported pictures is as crisp at 4096 px as at 800 px
// and nothing is looked up at run time. GL-free.
#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "render/color_map.hpp"
#include "render/image.hpp"

namespace pl {

// The TrueType file's bytes, e.g. for the editor's font atlas (ImGui's AddFontFromMemoryTTF, with
// FontDataOwnedByAtlas = false: the bytes are static).
std::span<const unsigned char> embedded_font_data();

class Font {
 public:
  // The embedded face, parsed once.
  static const Font& labels();
  // Throws std::runtime_error when the bytes are not a TrueType font; they must outlive the Font.
  explicit Font(std::span<const unsigned char> ttf);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  // Metrics in pixels of the font at size `px` (the em square's height): above the baseline, below
  // it (positive), and the height of a capital letter.
  double ascent(double px) const;
  double descent(double px) const;
  double cap_height(double px) const;
  // Advance width of UTF-8 text (kerning included); characters the font lacks count as its
  // missing-glyph box.
  double width(std::string_view utf8, double px) const;
  // Draws UTF-8 text with its baseline at y (pixels from the top) starting at x, blended over the
  // image with coverage times alpha.
  void draw(Image& image, double x, double baseline, std::string_view utf8, double px,
            const Rgb& rgb, float alpha = 1.0f) const;

 private:
  struct Face;
  std::unique_ptr<Face> face_;
};

}  // namespace pl
