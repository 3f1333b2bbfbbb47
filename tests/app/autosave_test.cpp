// The editor's crash recovery, GUI-free: when autosaves are written, where, atomically, what a
// later start is offered, and that a save removes them.
#include "app/editor/logic/autosave.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_test_util.hpp"
#include "core/io/scene_io.hpp"

namespace pl::test {
namespace {

using namespace std::chrono_literals;

long dead_pid() {  // a child that has exited and been reaped: certainly not running
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

Scene sample_scene() {
  return read_scene(PATCHLAB_SOURCE_DIR "/assets/default.json");
}

std::size_t entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) n += 1, (void)e;
  return n;
}

TEST(Autosave, WritesOnlyWhileDirtyAndAtMostEveryInterval) {
  TempDir dir;
  const auto state = dir / "state";
  Autosave a(state, 3000ms);
  const Scene scene = sample_scene();
  const auto t0 = Autosave::Clock::now();
  EXPECT_FALSE(a.tick(scene, false, "/docs/x.json", t0));  // clean: nothing to keep
  EXPECT_FALSE(std::filesystem::exists(state));
  EXPECT_TRUE(a.tick(scene, true, "/docs/x.json", t0));
  EXPECT_EQ(slurp(*a.file()), scene_to_json(scene));
  EXPECT_FALSE(a.tick(scene, true, "/docs/x.json", t0 + 2999ms));
  EXPECT_TRUE(a.tick(scene, true, "/docs/x.json", t0 + 3000ms));
  EXPECT_EQ(entries(state), 2u);  // the scene and its .info, no temporaries
  a.discard();                    // saved
  EXPECT_EQ(entries(state), 0u);
  EXPECT_TRUE(a.tick(scene, true, "", t0 + 3001ms));  // dirty again: at once
}

TEST(Autosave, NothingIsWrittenToTheWorkingDirectory) {
  TempDir dir;
  const auto cwd = std::filesystem::current_path();
  std::filesystem::create_directories(dir / "work");
  std::filesystem::current_path(dir / "work");
  Autosave a(dir / "state");
  a.tick(sample_scene(), true, "x.json", Autosave::Clock::now());
  Autosave none(std::nullopt);  // no home directory: no autosave at all
  EXPECT_FALSE(none.tick(sample_scene(), true, "x.json", Autosave::Clock::now()));
  EXPECT_EQ(entries(dir / "work"), 0u);
  std::filesystem::current_path(cwd);
}

TEST(Autosave, ALaterStartIsOfferedTheWorkOfADeadEditorOnly) {
  TempDir dir;
  const auto state = dir / "state";
  const long gone = dead_pid();
  Autosave crashed(state, 3000ms, gone);
  Scene edited = sample_scene();
  edited.network->vertices[0].z += 0.25;  // the unsaved edit
  ASSERT_TRUE(crashed.tick(edited, true, "/docs/default.json", Autosave::Clock::now()));
  Autosave running(state);  // this process: alive
  running.tick(sample_scene(), true, "", Autosave::Clock::now());

  Autosave next(state);
  const auto offers = next.pending();
  ASSERT_EQ(offers.size(), 1u);  // not the running editor's own
  EXPECT_EQ(offers[0].document, "/docs/default.json");
  const Scene back = Autosave::recover(offers[0]);
  EXPECT_EQ(scene_to_json(back), scene_to_json(edited));
  Autosave::drop(offers[0]);
  EXPECT_TRUE(next.pending().empty());
  EXPECT_EQ(entries(state), 2u);  // the running editor's pair only
}

TEST(Autosave, AFailedWriteIsReportedNotThrown) {
  TempDir dir;
  const auto blocker = dir.file("state", "a file where the directory should be");
  Autosave a(blocker / "patchlab");
  EXPECT_FALSE(a.tick(sample_scene(), true, "", Autosave::Clock::now()));
  EXPECT_NE(a.last_error().find("cannot write"), std::string::npos) << a.last_error();
}

}  // namespace
}  // namespace pl::test
