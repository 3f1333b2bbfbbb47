// The dependency rule of the design card: core/ knows no GL, GLFW, ImGui, render/ or app/;
// render/ knows no GLFW, ImGui or app/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace {

std::vector<std::string> offending(const std::string& folder, const std::regex& forbidden) {
  std::vector<std::string> bad;
  const std::filesystem::path root = std::filesystem::path(PATCHLAB_SOURCE_DIR) / folder;
  if (!std::filesystem::exists(root)) return bad;
  const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    const auto ext = e.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp" && ext != ".h" && ext != ".cc") continue;
    std::ifstream in(e.path());
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      std::smatch m;
      if (std::regex_search(line, m, include) && std::regex_search(m[1].str(), forbidden))
        bad.push_back(e.path().string() + ":" + std::to_string(n) + ": " + m[1].str());
    }
  }
  return bad;
}

TEST(Layering, CoreIncludesNoGraphicsUiRenderOrApp) {
  const auto bad = offending(
      "core", std::regex(R"(^(GL/|GLES|GLFW/|EGL/|KHR/|epoxy/|imgui|backends/|render/|app/))"));
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, RenderIncludesNoWindowUiOrApp) {
  const auto bad = offending("render", std::regex(R"(^(GLFW/|imgui|backends/|app/))"));
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, TheCheckItselfCatchesAViolation) {
  // Guard against a check that can never fail: the app folder does include core headers.
  EXPECT_FALSE(offending("app", std::regex(R"(^core/)")).empty());
}

}  // namespace
