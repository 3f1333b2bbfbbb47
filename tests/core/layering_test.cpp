// The dependency rule of the design card: core/ knows no GL, GLFW, ImGui, render/ or app/;
// render/ knows no GLFW, ImGui or app/; the editor's logic (app/editor/logic) knows no window,
// UI or GL.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

// The header named by an #include line, or "" for any other line.
std::string included(const std::string& line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return "";
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return "";
  const std::size_t open = line.find_first_of("<\"", i + 7);
  if (open == std::string::npos) return "";
  const std::size_t close = line.find_first_of(">\"", open + 1);
  return close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

std::vector<std::string> offending(const std::string& folder,
                                   const std::vector<std::string>& forbidden_prefixes) {
  std::vector<std::string> bad;
  const std::filesystem::path root = std::filesystem::path(PATCHLAB_SOURCE_DIR) / folder;
  if (!std::filesystem::exists(root)) return bad;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    const auto ext = e.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp" && ext != ".h" && ext != ".cc") continue;
    std::ifstream in(e.path());
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      const std::string header = included(line);
      for (const std::string& prefix : forbidden_prefixes)
        if (!header.empty() && header.rfind(prefix, 0) == 0)
          bad.push_back(e.path().string() + ":" + std::to_string(n) + ": " + header);
    }
  }
  return bad;
}

TEST(Layering, CoreIncludesNoGraphicsUiRenderOrApp) {
  const auto bad = offending("core", {"GL/", "GLES", "GLFW/", "EGL/", "KHR/", "epoxy/", "imgui",
                                      "backends/", "render/", "app/"});
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, RenderIncludesNoWindowUiOrApp) {
  const auto bad = offending("render", {"GLFW/", "imgui", "backends/", "app/"});
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, EditorLogicIncludesNoWindowUiOrGl) {
  // The editor's logic is GUI-free: it may use the renderer's plain data (cameras, draw scenes,
  // display settings) but nothing that needs a window or a GL context.
  const auto bad = offending(
      "app/editor/logic",
      {"GL/", "GLES", "GLFW/", "EGL/", "KHR/", "epoxy/", "imgui", "backends/", "render/gl",
       "render/gpu_scene", "render/scene_renderer", "render/egl_context", "render/offscreen_target",
       "render/frame", "app/editor/evaluated_view", "app/editor/gl_window"});
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, TheCheckItselfCatchesAViolation) {
  // Guard against a check that can never fail: the app folder does include core headers.
  EXPECT_FALSE(offending("app", {"core/"}).empty());
  EXPECT_EQ(included("  #  include <GLFW/glfw3.h>"), "GLFW/glfw3.h");
  EXPECT_EQ(included("// #include is mentioned"), "");
}

}  // namespace
