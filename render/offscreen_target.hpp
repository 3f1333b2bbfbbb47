// A multisampled offscreen framebuffer (colour + depth) and its single-sampled resolve target,
// read back into an Image. Needs a current context.
#pragma once

#include "render/gl_objects.hpp"
#include "render/image.hpp"

namespace pl {

class OffscreenTarget {
 public:
  // samples is clamped to the driver's GL_MAX_SAMPLES. Throws std::runtime_error when the
  // driver refuses the size or format.
  OffscreenTarget(int width, int height, int samples = 4);
  int width() const { return width_; }
  int height() const { return height_; }
  void bind() const;  // as the draw framebuffer, viewport = whole target
  // Resolves the samples and copies the pixels into `image` at (x, y) (top-left origin of the
  // image, which is flipped from GL's bottom-left). Alpha is un-premultiplied.
  void read_into(Image& image, int x, int y) const;

  // The largest square side one target may have on this driver.
  static int max_size();

 private:
  int width_, height_;
  gl::Framebuffer msaa_fbo_, resolve_fbo_;
  gl::Renderbuffer msaa_color_, msaa_depth_, resolve_color_;
};

}  // namespace pl
