// A single-sampled framebuffer (colour + depth) that a view is drawn into at a reduced
// resolution and then stretched onto the window (linear filtering): the editor's drawing while
// something moves, when full-resolution frames would not hold the frame rate. Grows or shrinks
// to the size asked for. Needs a current context.
#pragma once

#include "render/gl_objects.hpp"

namespace pl {

class ReducedTarget {
 public:
  // Binds the target at `width` x `height` (reallocated when the size changed) as the draw
  // framebuffer. Throws std::runtime_error when the driver refuses the size.
  void bind(int width, int height);
  // Copies the target, stretched, into the window's framebuffer rectangle (x, y, width,
  // height: GL's bottom-left origin) and binds the window's framebuffer again.
  void blit_to_window(int x, int y, int width, int height) const;

 private:
  int width_ = 0, height_ = 0;
  gl::Framebuffer fbo_;
  gl::Renderbuffer color_, depth_;
};

}  // namespace pl
