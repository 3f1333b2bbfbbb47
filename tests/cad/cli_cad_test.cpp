// `patchlab export OUT.step|.igs`: the report, the options, and the failures that must leave no
// file behind (a missing directory, a directory as target, a read-only file system, a full disk).
// The last two mount small tmpfs file systems, which needs root (CI runs as root); elsewhere
// they are skipped, saying why.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <sstream>

#include "app/cli/cli.hpp"
#include "cad_test_util.hpp"

namespace pl::test {
namespace {

struct CliRun {
  int code;
  std::string out, err;
};
CliRun cli(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

class Dir {
 public:
  Dir() {
    path_ = std::filesystem::temp_directory_path() /
            ("patchlab-cli-cad-" + std::to_string(std::random_device()()));
    std::filesystem::create_directories(path_);
  }
  ~Dir() {
    if (mounted_) ::umount(path_.c_str());
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  // A tmpfs of `size` over the directory (read-only if asked); false if that is not possible.
  bool mount_tmpfs(const char* size, bool read_only) {
    if (::geteuid() != 0) return false;
    const std::string options = std::string("size=") + size;
    mounted_ =
        ::mount("tmpfs", path_.c_str(), "tmpfs", read_only ? MS_RDONLY : 0, options.c_str()) == 0;
    return mounted_;
  }
  std::filesystem::path operator/(const std::string& n) const { return path_ / n; }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_))
      names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
  bool mounted_ = false;
};

std::string asset(const char* name) {
  return (source_dir() / "assets" / name).string();
}

// The 96-face cube-sphere scene (its STEP file is about 700 kB).
std::string cube_sphere(const Dir& dir) {
  const auto f = dir / "cs4.json";
  const CliRun r = cli({"sample", "cube-sphere", "--cells", "4", "-o", f.string()});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  return f.string();
}

TEST(CadCli, ExportWritesStepAndReportsEveryFaceAndTheShell) {
  Dir dir;
  const auto out = dir / "blob.stp";
  const CliRun r = cli({"export", asset("gregory-blob-closed.json"), "-o", out.string()});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
  EXPECT_NE(r.out.find("wrote 24 face(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("STEP AP242"), std::string::npos);
  EXPECT_NE(r.out.find("bottom-quad"), std::string::npos);  // a face's own line
  EXPECT_NE(r.out.find("1 closed, 1 solid(s); 0 free edge(s)"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // OpenCASCADE's own messages are silenced
}

TEST(CadCli, ToleranceOptionIsUsedAndChecked) {
  Dir dir;
  const auto out = dir / "d.igs";
  CliRun r = cli({"export", asset("default.json"), "-o", out.string(), "--tolerance", "0.0001"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("fitted to 0.0001 and 0.05 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("IGES"), std::string::npos);
  for (const char* bad : {"0", "-1", "abc", "1e-3x", "inf"}) {
    r = cli({"export", asset("default.json"), "-o", (dir / "x.step").string(), "--tolerance", bad});
    EXPECT_EQ(r.code, kExitUsage) << bad;
  }
  r = cli({"export", asset("default.json"), "-o", (dir / "x.step").string(), "--density", "8"});
  EXPECT_EQ(r.code, kExitUsage);
  r = cli({"export", asset("default.json"), "-o", (dir / "x.obj").string(), "--tolerance", "1"});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.step"));
}

TEST(CadCli, MissingDirectoryAndDirectoryTargetFailWithoutAFile) {
  Dir dir;
  const auto missing = dir / "no/such/dir/out.step";
  CliRun r = cli({"export", asset("bezier-wave.json"), "-o", missing.string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find(missing.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no directory"), std::string::npos) << r.err;
  std::filesystem::create_directories(dir / "folder.step");
  r = cli({"export", asset("bezier-wave.json"), "-o", (dir / "folder.step").string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"folder.step"});
}

TEST(CadCli, ReadOnlyFileSystemFailsWithoutAFile) {
  Dir dir;
  if (!dir.mount_tmpfs("64k", true)) GTEST_SKIP() << "mounting a read-only tmpfs needs root";
  const auto out = dir / "out.step";
  const CliRun r = cli({"export", asset("bezier-wave.json"), "-o", out.string()});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Read-only file system"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one message
  EXPECT_TRUE(dir.listing().empty());
}

TEST(CadCli, FullDiskFailsAndKeepsThePreviousFile) {
  Dir work;
  const std::string scene = cube_sphere(work);
  Dir dir;
  if (!dir.mount_tmpfs("64k", false)) GTEST_SKIP() << "mounting a tmpfs needs root";
  for (const char* name : {"out.step", "out.iges"}) {
    const auto out = dir / name;
    std::ofstream(out) << "previous";
    const CliRun r = cli({"export", scene, "-o", out.string()});
    EXPECT_EQ(r.code, kExitBadInput);
    EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
    std::ifstream in(out);
    std::string content;
    std::getline(in, content);
    EXPECT_EQ(content, "previous");
    EXPECT_EQ(dir.listing(), std::vector<std::string>{name});  // no temporary file left
    std::filesystem::remove(out);
  }
}

}  // namespace
}  // namespace pl::test
