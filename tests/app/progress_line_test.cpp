// The command line's progress line: written (and erased at the end) on a terminal once the work
// takes longer than its delay, nothing at all otherwise.
#include "app/cli/progress_line.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <thread>

namespace pl {
namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[256];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, f)) s.append(buf, n);
  return s;
}

TEST(ProgressLine, OnATerminalLongWorkIsShownAndErasedAtTheEnd) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressLine line("patchlab export", f, true, std::chrono::milliseconds(0));
    ProgressLine::set_stage("evaluating the surfaces");
    std::this_thread::sleep_for(std::chrono::milliseconds(450));
  }
  const std::string s = contents(f);
  std::fclose(f);
  EXPECT_NE(s.find("patchlab export: evaluating the surfaces ("), std::string::npos) << s;
  EXPECT_EQ(s.substr(s.size() - 4), "\r\033[K") << "the line is not erased";
  EXPECT_EQ(s.find('\n'), std::string::npos) << "the line is rewritten in place";
}

TEST(ProgressLine, ShortWorkAndNonTerminalsGetNothing) {
  for (const bool terminal : {true, false}) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
      // A terminal with an hour's delay: the work ends first. No terminal: never.
      ProgressLine line("patchlab export", f, terminal,
                        terminal ? std::chrono::hours(1) : std::chrono::milliseconds(0));
      line.stage("evaluating the surfaces");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_EQ(contents(f), "") << (terminal ? "terminal" : "not a terminal");
    std::fclose(f);
  }
}

}  // namespace
}  // namespace pl
