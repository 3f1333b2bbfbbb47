// The reader's view of the bytes around a JSON value: nothing but white space may follow it (a
// NUL byte ended the parse early, so a value followed by one, and by anything after it, was
// read), and integers beyond 64 bits are reported as too large, not as fractions.
#include <gtest/gtest.h>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

const std::string kScene = R"({"patchlab": 1, "name": "x"})";

std::string refusal(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const DataError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(JsonTextEnd, WhiteSpaceMayFollowTheValue) {
  EXPECT_EQ(parse_scene(kScene + " \n\t\r\n", "s.json").name, "x");
}

TEST(JsonTextEnd, ANulByteIsRefusedWhereverItIs) {
  for (const std::string& tail :
       {std::string(1, '\0'), std::string("\0junk", 5), std::string("\n\0", 2)}) {
    const std::string e = refusal(kScene + tail);
    EXPECT_NE(e.find("s.json: line "), std::string::npos) << e;
    EXPECT_NE(e.find("a NUL byte"), std::string::npos) << e;
  }
  // Located: the NUL after "\n" is on line 2, column 1.
  EXPECT_NE(refusal(kScene + std::string("\n\0", 2)).find("line 2, column 1"), std::string::npos);
  // Inside the value too (a raw NUL is never valid JSON, not even in a string).
  const std::string inside = std::string(R"({"patchlab": 1, "name": "a)") + '\0' + R"(b"})";
  EXPECT_NE(refusal(inside).find("a NUL byte"), std::string::npos);
}

TEST(JsonTextEnd, EveryOtherTrailingByteIsRefusedAsBefore) {
  for (const std::string tail : {"x", "}", "\x01", "\xff"}) {
    const std::string e = refusal(kScene + tail);
    EXPECT_NE(e.find("invalid JSON"), std::string::npos) << e;
  }
}

std::string with_degree(const std::string& first) {
  return R"({"patchlab": 1, "patches": [{"type": "bezier", "degree": [)" + first +
         R"(, 1], "points": []}]})";
}

TEST(JsonTextEnd, IntegersBeyond64BitsAreOutOfRangeNotFractional) {
  for (const std::string big :
       {"18446744073709551617", "-9223372036854775809", "100000000000000000000000", "1e30"}) {
    const std::string e = refusal(with_degree(big));
    EXPECT_NE(e.find("patches[0].degree[0]: integer"), std::string::npos) << big << ": " << e;
    EXPECT_NE(e.find("out of range"), std::string::npos) << big << ": " << e;
    EXPECT_EQ(e.find("fractional"), std::string::npos) << big << ": " << e;
  }
  EXPECT_NE(refusal(with_degree("1.5")).find("a fractional number"), std::string::npos);
}

}  // namespace
}  // namespace pl
