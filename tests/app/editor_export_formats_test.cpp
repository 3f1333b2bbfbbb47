// The export formats' names: which format a file name names, and the file an export in a chosen
// format writes for a typed name (its extension added, or the name refused with the reason).
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "app/editor/logic/export_formats.hpp"

namespace pl {

namespace {

namespace fs = std::filesystem;

const ExportFormat& format(const std::string& id) {
  for (const ExportFormat& f : export_formats())
    if (f.id == id) return f;
  throw std::logic_error("no format " + id);
}

std::string refusal(const fs::path& p, const ExportFormat* f) {
  try {
    export_target(p, f);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExportFormats, EveryExtensionNamesOneFormat) {
  std::set<std::string> seen;
  for (const ExportFormat& f : export_formats()) {
    ASSERT_FALSE(f.extensions.empty()) << f.id;
    for (const std::string& e : f.extensions) {
      EXPECT_TRUE(seen.insert(e).second) << e << " is two formats' extension";
      EXPECT_EQ(export_format_of(fs::path("a") += e), &f) << e;
    }
  }
  EXPECT_EQ(export_format_of("part.STP"), &format("step")) << "any letter case";
  EXPECT_EQ(export_format_of("part.Iges"), &format("iges"));
  EXPECT_EQ(export_format_of("part"), nullptr);
  EXPECT_EQ(export_format_of("part.json"), nullptr);
  EXPECT_TRUE(format("step").cad);
  EXPECT_FALSE(format("obj").cad);
}

TEST(ExportFormats, TheChosenFormatGivesANameItsExtension) {
  const ExportFormat* step = &format("step");
  EXPECT_EQ(export_target("dir/part", step), fs::path("dir/part.step"));
  EXPECT_EQ(export_target("dir/part.v2", step), fs::path("dir/part.v2.step"));
  EXPECT_EQ(export_target("dir/part.stp", step), fs::path("dir/part.stp")) << "its own: kept";
  EXPECT_EQ(export_target("dir/part.STEP", step), fs::path("dir/part.STEP"));
  EXPECT_EQ(export_target("mesh.off", nullptr), fs::path("mesh.off")) << "no choice: the name's";

  const std::string other = refusal("dir/part.obj", step);
  EXPECT_NE(other.find(".obj"), std::string::npos) << other;
  EXPECT_NE(other.find("STEP"), std::string::npos) << other;
  for (const char* name : {"dir/part", "dir/part.xyz"}) {
    const std::string none = refusal(name, nullptr);
    EXPECT_NE(none.find(".stl"), std::string::npos) << name << ": " << none;
    EXPECT_NE(none.find(".iges"), std::string::npos) << name << ": " << none;
  }
  EXPECT_FALSE(refusal("dir/", step).empty()) << "no file name";
}

}  // namespace pl
