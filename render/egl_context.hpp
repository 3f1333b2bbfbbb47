// A headless OpenGL 3.3 core context made with EGL: no window and no X server. Context creation
// is kept apart from drawing, so the same renderer can later draw into a GLFW window instead.
#pragma once

#include <stdexcept>
#include <string>

namespace pl {

// No usable OpenGL context could be made (no EGL display, no GL 3.3 core support, ...).
struct GlContextError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class EglContext {
 public:
  // Tries the Mesa surfaceless platform, then EGL devices, then EGL_DEFAULT_DISPLAY, and makes
  // the context current on this thread. Throws GlContextError saying what each attempt found.
  // The context current before (if any) is current again after the destructor (or the throw),
  // and its display is left initialised.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Which display platform succeeded ("surfaceless", "device", "default").
  const std::string& platform() const { return platform_; }

 private:
  void release(void* display) const;
  void restore_previous() const;
  // The context current when this one was made: EGLDisplay, EGLContext, EGLSurface draw, read.
  void *previous_display_, *previous_context_, *previous_draw_, *previous_read_;
  void* display_ = nullptr;  // EGLDisplay, kept opaque so EGL headers stay out of this header
  void* context_ = nullptr;  // EGLContext
  std::string platform_;
};

}  // namespace pl
