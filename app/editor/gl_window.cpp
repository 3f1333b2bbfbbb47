#include "app/editor/gl_window.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "app/editor/theme.hpp"
#include "render/gl.hpp"

namespace pl {

namespace {
std::string last_glfw_error;
void on_glfw_error(int, const char* description) {
  last_glfw_error = description;
}
}  // namespace

GlWindow::GlWindow(int width, int height, const std::string& title,
                   const std::filesystem::path& ini_file)
    : ini_file_(ini_file.string()) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit())
    throw WindowError("cannot open a window (" + last_glfw_error +
                      "); the editor needs a display, the sub-commands do not");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // No multisampling: llvmpipe (CPU rendering) pays for every sample, and the renderer's lines
  // and points are anti-aliased in their shaders already.
  glfwWindowHint(GLFW_SAMPLES, 0);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw WindowError("cannot create an OpenGL 3.3 core window (" + last_glfw_error + ")");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the loop waits for events itself; vsync would cap drags under Xvfb

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // Never the working directory: the layout lives under $XDG_STATE_HOME/patchlab, or nowhere.
  io.IniFilename = ini_file_.empty() ? nullptr : ini_file_.c_str();
  // No keyboard navigation of the panels: single keys belong to the 3D view (F, C, 1, arrows).
  apply_theme();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  imgui_ready_ = true;
}

GlWindow::~GlWindow() {
  if (imgui_ready_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlWindow::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

float GlWindow::content_scale() const {
  float x = 1, y = 1;
  glfwGetWindowContentScale(window_, &x, &y);
  return std::max(x, y) > 0 ? std::max(x, y) : 1.0f;
}

void GlWindow::apply_ui_scale(float scale) {
  int fw = 0, fh = 0, ww = 0, wh = 0;
  glfwGetFramebufferSize(window_, &fw, &fh);
  glfwGetWindowSize(window_, &ww, &wh);
  load_ui_font(scale, ww > 0 && fw > 0 ? float(fw) / float(ww) : 1.0f);
  ui_scale_ = scale;
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGui::GetStyle() = ImGuiStyle();
  apply_theme();
  ImGui::GetStyle().ScaleAllSizes(scale);
}

float GlWindow::follow_ui_scale(double preference) {
  // Moved to a monitor with another content scale (or the preference changed): new fonts and
  // sizes, between two frames.
  const float want = preference > 0 ? float(preference) : content_scale();
  if (want != ui_scale_) apply_ui_scale(want);
  return ui_scale_;
}

void GlWindow::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void GlWindow::end_frame() {
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glViewport(0, 0, w, h);
  glDisable(GL_SCISSOR_TEST);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
}

void GlWindow::poll_events() {
  glfwPollEvents();
}

void GlWindow::wait_events(double seconds) {
  glfwWaitEventsTimeout(seconds);
}

void GlWindow::wake() {
  glfwPostEmptyEvent();
}

void GlWindow::on_key(std::function<void(int, int)> handler) {
  key_handler_ = std::move(handler);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
    ImGui_ImplGlfw_KeyCallback(w, key, scancode, action, mods);  // ImGui's state stays current
    auto* self = static_cast<GlWindow*>(glfwGetWindowUserPointer(w));
    if (action != GLFW_RELEASE && self->key_handler_) self->key_handler_(key, mods);
  });
}

void GlWindow::on_drop(std::function<void(const std::string&)> handler) {
  drop_handler_ = std::move(handler);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<GlWindow*>(glfwGetWindowUserPointer(w));
    if (!self->drop_handler_) return;
    for (int i = 0; i < count; ++i) self->drop_handler_(paths[i]);
  });
}

bool GlWindow::take_close_request() {
  if (!glfwWindowShouldClose(window_)) return false;
  glfwSetWindowShouldClose(window_, GLFW_FALSE);
  return true;
}

std::pair<int, int> GlWindow::framebuffer_size() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {w, h};
}

std::pair<int, int> GlWindow::window_size() const {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  return {w, h};
}

std::pair<int, int> GlWindow::position() const {
  int x = 0, y = 0;
  glfwGetWindowPos(window_, &x, &y);
  return {x, y};
}

}  // namespace pl
