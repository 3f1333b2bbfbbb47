// The repository stands on its own: every file path that `patchlab --help`, the README and the
// documents in docs/ name exists in it, and none of them points outside it.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

#include "cli_test_util.hpp"

namespace pl::test {
namespace {

const std::filesystem::path kRoot(PATCHLAB_SOURCE_DIR);

// Paths into the repository's top-level folders named in text: "docs/cli.md",
// "core/patch/gb/blend.hpp", "tests/data/gb/". Patterns with wildcards or placeholders
// ("core/io/*_codec*.cpp", "app/cli/<name>_command.cpp") are not paths and are left out.
std::set<std::string> named_paths(const std::string& text) {
  static const std::regex path(
      R"((?:^|[\s`("'])((?:core|docs|tests|assets|app|render|shaders|\.ci)/[A-Za-z0-9_.*<>{}/+-]*))");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), path); it != std::sregex_iterator();
       ++it) {
    std::string p = (*it)[1].str();
    while (!p.empty() && (p.back() == '.' || p.back() == ',' || p.back() == ':')) p.pop_back();
    if (p.find_first_of("*<>{}") != std::string::npos) continue;
    out.insert(p);
  }
  return out;
}

// A path exists, or names a C++ unit by its stem ("core/eval/density_choice": the .hpp/.cpp).
bool exists_in_repo(const std::string& p) {
  return std::filesystem::exists(kRoot / p) || std::filesystem::exists(kRoot / (p + ".hpp")) ||
         std::filesystem::exists(kRoot / (p + ".cpp"));
}

std::vector<std::filesystem::path> documents() {
  std::vector<std::filesystem::path> docs{kRoot / "README.md", kRoot / "tests/data/gb/README.md"};
  for (const auto& e : std::filesystem::directory_iterator(kRoot / "docs"))
    if (e.path().extension() == ".md") docs.push_back(e.path());
  return docs;
}

TEST(DocsPaths, EveryPathTheDocumentsNameExists) {
  int checked = 0;
  for (const auto& doc : documents()) {
    const std::string text = slurp(doc);
    ASSERT_FALSE(text.empty()) << doc;
    // A path that leaves the repository (written in two pieces, so this file does not name it).
    EXPECT_EQ(text.find(std::string("..") + "/shared"), std::string::npos)
        << doc << " points outside the repository";
    for (const std::string& p : named_paths(text)) {
      ++checked;
      EXPECT_TRUE(exists_in_repo(p)) << doc.filename() << " names " << p;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(DocsPaths, EveryPathTheHelpNamesExists) {
  const auto r = cli({"--help"});
  ASSERT_EQ(r.code, 0);
  const auto paths = named_paths(r.out);
  EXPECT_TRUE(paths.count("docs/scene-format.md"));
  EXPECT_TRUE(paths.count("docs/cli.md"));
  for (const std::string& p : paths) EXPECT_TRUE(exists_in_repo(p)) << p;
}

TEST(DocsPaths, TheCheckFindsPathsAndSkipsPatterns) {
  const auto p = named_paths("see `docs/cli.md`, core/io/*_codec*.cpp and (tests/data/gb/).");
  EXPECT_EQ(p, (std::set<std::string>{"docs/cli.md", "tests/data/gb/"}));
}

}  // namespace
}  // namespace pl::test
