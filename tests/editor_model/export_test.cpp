// File > Export with a format chosen (File > Export As > ...): the chosen format decides what is
// written and gives a name typed without an extension its own; without a choice the typed
// extension decides, and a name that names no format, or another format than the one chosen, is
// refused with a message that says which names work, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "model_driver.hpp"

namespace pl::test {

namespace {

namespace fs = std::filesystem;

const fs::path kDefaultScene = fs::path(PATCHLAB_SOURCE_DIR) / "assets" / "default.json";

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(Export, TheFormatChosenDecidesAndNamesANameWithoutExtension) {
  TempDir dir("export");
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  m.open_file(kDefaultScene);
  d.settle();

  ASSERT_TRUE(m.actions().run("file.export.ply"));
  ASSERT_TRUE(m.export_format());
  EXPECT_EQ(m.export_format()->id, "ply");
  m.export_file(dir.path() / "shape");
  EXPECT_EQ(d.shell().errors, 0) << d.shell().last_error;
  ASSERT_TRUE(fs::exists(dir.path() / "shape.ply")) << "the chosen format's extension is added";
  EXPECT_EQ(first_line(dir.path() / "shape.ply"), "ply") << "and a PLY file is written";
  EXPECT_FALSE(fs::exists(dir.path() / "shape"));

  // A name ending in another format's extension: refused, nothing written.
  m.export_file(dir.path() / "shape.stl");
  EXPECT_EQ(d.shell().errors, 1);
  EXPECT_TRUE(contains(d.shell().last_error, "PLY")) << d.shell().last_error;
  EXPECT_TRUE(contains(d.shell().last_error, ".stl")) << d.shell().last_error;
  EXPECT_FALSE(fs::exists(dir.path() / "shape.stl"));
}

TEST(Export, WithoutAChoiceANameThatNamesNoFormatIsRefusedWithTheList) {
  TempDir dir("export-plain");
  ModelDriver d(1280, 720);
  EditorModel& m = d.model();
  m.open_file(kDefaultScene);
  d.settle();

  ASSERT_TRUE(m.actions().run("file.export"));
  EXPECT_FALSE(m.export_format()) << "File > Export...: the extension decides";
  for (const char* name : {"shape", "shape.xyz"}) {
    const int before = d.shell().errors;
    m.export_file(dir.path() / name);
    EXPECT_EQ(d.shell().errors, before + 1) << name;
    for (const char* listed : {".obj", ".ply", ".off", ".stl", ".step", ".igs"})
      EXPECT_TRUE(contains(d.shell().last_error, listed)) << d.shell().last_error;
    EXPECT_TRUE(fs::is_empty(dir.path())) << name << ": nothing is written";
  }
  m.export_file(dir.path() / "shape.OBJ");
  EXPECT_EQ(d.shell().errors, 2) << d.shell().last_error;
  EXPECT_TRUE(fs::exists(dir.path() / "shape.OBJ"));
}

}  // namespace pl::test
