// The editor's window: GLFW with an OpenGL 3.3 core context, and Dear ImGui's context and
// GLFW/OpenGL3 backends. One object owns all of it, so they are torn down in the right order.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

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

  void begin_frame();  // starts an ImGui frame
  void end_frame();    // renders ImGui over whatever was drawn and swaps

  // Input: handles what arrived, or waits for it (at most `seconds`).
  void poll_events();
  void wait_events(double seconds);
  // Makes a waiting wait_events() return: from any thread (a worker that finished).
  static void wake();
  // Key presses (GLFW key and modifiers; ImGui sees them too) and dropped files, as they come.
  void on_key(std::function<void(int key, int mods)> handler);
  void on_drop(std::function<void(const std::string& path)> handler);
  // The user asked to close the window (the window stays open: the editor decides); true once
  // per request.
  bool take_close_request();

  // Sizes in pixels: the framebuffer's (HiDPI: larger) and the window's; its position on screen.
  std::pair<int, int> framebuffer_size() const;
  std::pair<int, int> window_size() const;
  std::pair<int, int> position() const;

 private:
  GLFWwindow* window_ = nullptr;
  std::function<void(int, int)> key_handler_;
  std::function<void(const std::string&)> drop_handler_;
  std::string ini_file_;  // kept alive: ImGui stores the pointer
  bool imgui_ready_ = false;
  float ui_scale_ = 0;  // applied
};

}  // namespace pl
