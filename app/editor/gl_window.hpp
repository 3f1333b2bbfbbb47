// The editor's window: GLFW with an OpenGL 3.3 core context, and Dear ImGui's context and
// GLFW/OpenGL3 backends. One object owns all of it, so they are torn down in the right order.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace pl {

struct WindowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GlWindow {
 public:
  // Throws WindowError (no display, no GL 3.3). `ini_file` is ImGui's layout file (empty: none).
  GlWindow(int width, int height, const std::string& title, const std::filesystem::path& ini_file);
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  void set_title(const std::string& title);
  // The monitor's content scale (1 on a standard display, 2 on HiDPI).
  float content_scale() const;
  // Applies a UI scale: fonts (the embedded TrueType face) and widget sizes.
  void apply_ui_scale(float scale);
  // Applies `preference` (> 0), or else the monitor's content scale, when it differs from the
  // scale applied; returns the scale in use. Call before begin_frame().
  float follow_ui_scale(double preference);

  void begin_frame();  // polls events, starts an ImGui frame
  void end_frame();    // renders ImGui over whatever was drawn and swaps

 private:
  GLFWwindow* window_ = nullptr;
  std::string ini_file_;  // kept alive: ImGui stores the pointer
  bool imgui_ready_ = false;
  float ui_scale_ = 0;  // applied
};

}  // namespace pl
