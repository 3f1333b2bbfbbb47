#include "render/offscreen_target.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace pl {

int OffscreenTarget::max_size() {
  GLint rb = 0, dims[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &rb);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
  return std::min({rb, dims[0], dims[1]});
}

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : width_(width), height_(height) {
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples = std::clamp(samples, 0, static_cast<int>(max_samples));

  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            msaa_color_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_.id());
  const GLenum msaa_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);

  glBindRenderbuffer(GL_RENDERBUFFER, resolve_color_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            resolve_color_.id());
  const GLenum resolve_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (msaa_status != GL_FRAMEBUFFER_COMPLETE || resolve_status != GL_FRAMEBUFFER_COMPLETE ||
      glGetError() != GL_NO_ERROR)
    throw std::runtime_error("the OpenGL driver cannot make a " + std::to_string(width) + "x" +
                             std::to_string(height) + " offscreen framebuffer");
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::read_into(Image& image, int x, int y) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.id());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.id());
  std::vector<uint8_t> pixels(static_cast<std::size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  for (int row = 0; row < height_; ++row) {
    const int iy = y + (height_ - 1 - row);
    if (iy < 0 || iy >= image.height) continue;
    for (int col = 0; col < width_; ++col) {
      const int ix = x + col;
      if (ix < 0 || ix >= image.width) continue;
      const uint8_t* s = &pixels[(static_cast<std::size_t>(row) * width_ + col) * 4];
      uint8_t* d = image.at(ix, iy);
      // Blending over a transparent clear leaves premultiplied colour; PNG wants straight alpha.
      const int a = s[3];
      for (int k = 0; k < 3; ++k)
        d[k] = (a == 0 || a == 255) ? s[k]
                                    : static_cast<uint8_t>(std::min(255, (s[k] * 255 + a / 2) / a));
      d[3] = s[3];
    }
  }
}

}  // namespace pl
