// The dependency rules of the code (docs/developing.md): core/ knows no GL, GLFW, ImGui, render/
// or app/; render/ knows no GLFW, ImGui or app/; the editor's logic (app/editor/logic) knows no
// window, UI or GL; the editor knows no app/cli; and inside core/ every folder stands on a floor
// and includes only folders on lower floors (or its own): no include runs up or sideways.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

// The floors of core/, lowest first. A new folder must be placed here explicitly: the test fails
// for a folder of core/ that is not in this table.
const std::map<std::string, int>& core_floors() {
  // clang-format off
  static const std::map<std::string, int> floors{
      {"base", 0},                                // DataError, parallel loops
      {"math", 1},                                // Jet, lanes, Bernstein, vectors
      {"curve", 2}, {"domain", 2}, {"param", 2},  // curves, parameter domains, parameterizations
      {"patch", 3},                               // every patch type
      {"geometry", 4}, {"scene", 4},              // differential geometry, the scene model
      {"io", 5}, {"network", 5},                  // file formats, filling curve networks
      {"eval", 6},                                // sampled surfaces, incremental updates
      {"mesh", 7}, {"analysis", 7},               // mesh export, surface-quality figures
      {"cad", 8},                                 // CAD export (the top of core)
  };
  // clang-format on
  return floors;
}

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

struct Include {
  std::filesystem::path file;  // relative to the source root
  int line;
  std::string header;
};

// Every #include of every C++ file under `folder` (relative to the source root).
std::vector<Include> includes_under(const std::string& folder) {
  std::vector<Include> out;
  const std::filesystem::path source(PATCHLAB_SOURCE_DIR);
  const std::filesystem::path root = source / folder;
  if (!std::filesystem::exists(root)) return out;
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
      if (!header.empty()) out.push_back({std::filesystem::relative(e.path(), source), n, header});
    }
  }
  return out;
}

std::vector<std::string> offending(const std::string& folder,
                                   const std::vector<std::string>& forbidden_prefixes) {
  std::vector<std::string> bad;
  for (const Include& inc : includes_under(folder))
    for (const std::string& prefix : forbidden_prefixes)
      if (inc.header.rfind(prefix, 0) == 0)
        bad.push_back(inc.file.string() + ":" + std::to_string(inc.line) + ": " + inc.header);
  return bad;
}

// The core folder a path inside core/ names ("core/patch/gb/blend.hpp" -> "patch"), or "".
std::string core_folder(const std::filesystem::path& p) {
  auto it = p.begin();
  if (it == p.end() || *it != "core") return "";
  ++it;
  if (it == p.end() || std::next(it) == p.end()) return "";  // a file directly in core/
  return it->string();
}

// An include of `header` by a file of folder `from` that does not go strictly down a floor (or
// stay in its folder), as a message; "" if it is fine.
std::string floor_violation(const std::string& from, const std::string& header,
                            const std::map<std::string, int>& floors) {
  const std::string to = core_folder(header);
  if (to.empty() || to == from) return "";
  const auto a = floors.find(from), b = floors.find(to);
  if (a == floors.end()) return "core/" + from + " has no floor";
  if (b == floors.end()) return "core/" + to + " has no floor";
  if (b->second < a->second) return "";
  return "core/" + from + " (floor " + std::to_string(a->second) + ") includes core/" + to +
         " (floor " + std::to_string(b->second) + ")";
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
       "render/frame", "app/editor/gpu_view_copy", "app/editor/gl_window"});
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, EveryCoreFolderHasAFloor) {
  const std::filesystem::path core = std::filesystem::path(PATCHLAB_SOURCE_DIR) / "core";
  ASSERT_TRUE(std::filesystem::is_directory(core));
  int folders = 0;
  for (const auto& e : std::filesystem::directory_iterator(core)) {
    if (!e.is_directory()) continue;
    ++folders;
    EXPECT_TRUE(core_floors().count(e.path().filename().string()))
        << "core/" << e.path().filename().string()
        << " is not in the floor table of tests/core/layering_test.cpp: place it there";
  }
  EXPECT_GE(folders, 10);
}

TEST(Layering, EditorIncludesNoCommandLine) {
  // The editor and the command line share the document (app/document) and the draw scene
  // (render/draw_scene_builder); neither reaches into the other.
  const auto bad = offending("app/editor", {"app/cli/"});
  EXPECT_TRUE(bad.empty()) << bad.front();
}

TEST(Layering, CoreIncludesRunOnlyDownTheFloors) {
  int checked = 0;
  for (const Include& inc : includes_under("core")) {
    const std::string from = core_folder(inc.file);
    ASSERT_FALSE(from.empty()) << inc.file << ": a file directly in core/ has no floor";
    const std::string why = floor_violation(from, inc.header, core_floors());
    EXPECT_TRUE(why.empty()) << inc.file.string() << ":" << inc.line << ": " << why;
    checked += !core_folder(inc.header).empty();
  }
  EXPECT_GT(checked, 100);  // the includes were read
}

TEST(Layering, TheChecksThemselvesCatchViolations) {
  // Guard against checks that can never fail: the app folder does include core headers, and
  // the floor rule refuses an include up, sideways, or into a folder without a floor.
  EXPECT_FALSE(offending("app", {"core/"}).empty());
  EXPECT_EQ(included("  #  include <GLFW/glfw3.h>"), "GLFW/glfw3.h");
  EXPECT_EQ(included("// #include is mentioned"), "");
  const auto& f = core_floors();
  EXPECT_EQ(floor_violation("patch", "core/math/jet.hpp", f), "");
  EXPECT_EQ(floor_violation("patch", "core/patch/gb/blend.hpp", f), "");
  EXPECT_NE(floor_violation("math", "core/patch/patch.hpp", f), "");    // up
  EXPECT_NE(floor_violation("io", "core/network/gb_face.hpp", f), "");  // sideways
  EXPECT_NE(floor_violation("eval", "core/newfolder/x.hpp", f), "");    // no floor
  EXPECT_EQ(core_folder("core/patch/gb/blend.hpp"), "patch");
  EXPECT_EQ(core_folder("core/CMakeLists.txt"), "");
}

}  // namespace
