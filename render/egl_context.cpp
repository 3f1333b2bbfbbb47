#include "render/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

namespace pl {

namespace {

// Returns a context on `display` or nullptr, appending the reason for a failure to `why`.
EGLContext make_context(EGLDisplay display, std::string& why) {
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    why += " (eglInitialize failed)";
    return EGL_NO_CONTEXT;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why += " (no desktop OpenGL API)";
    return EGL_NO_CONTEXT;
  }
  // EGL_SURFACE_TYPE 0: drawing goes to framebuffer objects, so any config will do.
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count < 1) {
    why += " (no OpenGL config)";
    return EGL_NO_CONTEXT;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    3,
                                    EGL_CONTEXT_MINOR_VERSION,
                                    3,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                    EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context == EGL_NO_CONTEXT) {
    why += " (no OpenGL 3.3 core context)";
    return EGL_NO_CONTEXT;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    why += " (cannot make a surfaceless context current)";
    return EGL_NO_CONTEXT;
  }
  return context;
}

}  // namespace

EglContext::EglContext()
    : previous_display_(eglGetCurrentDisplay()),
      previous_context_(eglGetCurrentContext()),
      previous_draw_(eglGetCurrentSurface(EGL_DRAW)),
      previous_read_(eglGetCurrentSurface(EGL_READ)) {
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));

  std::vector<std::pair<std::string, EGLDisplay>> candidates;
  if (get_platform_display) {
    candidates.emplace_back("surfaceless", get_platform_display(EGL_PLATFORM_SURFACELESS_MESA,
                                                                EGL_DEFAULT_DISPLAY, nullptr));
    EGLDeviceEXT devices[8];
    EGLint n = 0;
    if (query_devices && query_devices(8, devices, &n))
      for (EGLint i = 0; i < n; ++i)
        candidates.emplace_back("device",
                                get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
  }
  candidates.emplace_back("default", eglGetDisplay(EGL_DEFAULT_DISPLAY));

  std::string why;
  for (auto& [name, display] : candidates) {
    why += (why.empty() ? "" : ", ") + name;
    if (display == EGL_NO_DISPLAY) {
      why += " (no display)";
      continue;
    }
    EGLContext context = make_context(display, why);
    if (context != EGL_NO_CONTEXT) {
      display_ = display;
      context_ = context;
      platform_ = name;
      return;
    }
    release(display);
  }
  restore_previous();
  throw GlContextError("cannot create an OpenGL 3.3 core context with EGL; tried " + why);
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  // The display stays initialised for the life of the process: terminating it makes Mesa unload
  // its driver, so the next context (the benchmarks render many times) loads and compiles it all
  // again, and the driver's process-lifetime allocations are then reported as leaks from a
  // module that no longer exists.
  restore_previous();
}

void EglContext::release(void* display) const {
  // eglGetPlatformDisplay returns the same display each time and eglInitialize does not count:
  // terminating the display of the context that was current before would destroy that one too.
  if (display != previous_display_) eglTerminate(display);
}

void EglContext::restore_previous() const {
  // Whoever had a context current (the editor's window, a test program's shared context) still
  // has it once this one is gone.
  if (previous_context_ != EGL_NO_CONTEXT)
    eglMakeCurrent(previous_display_, previous_draw_, previous_read_, previous_context_);
}

}  // namespace pl
