// The reader takes a scene's curves one by one as the parser meets them (their JSON is not kept).
// Its errors must still come in the order of a reader that parsed the whole file first: a syntax
// error anywhere, then the top level, network and patches, then the first bad curve.
#include <gtest/gtest.h>

#include <string>

#include "core/base/data_error.hpp"
#include "core/io/scene_io.hpp"

namespace pl {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "s.json");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

const char* kBadCurve = R"({"type": "bezier", "points": [[0, 0, 0]]})";  // one point: too few
const char* kGoodCurve = R"({"type": "bezier", "points": [[0, 0, 0], [1, 0, 0]]})";

TEST(StreamedCurves, CurvesAreReadInOrderWithTheirPaths) {
  const Scene s = parse_scene(std::string(R"({"curves": [)") + kGoodCurve + "," +
                                  R"({"type": "bezier", "name": "b", "points": [[0,0,0],[0,2,0]]}],
                                  "patchlab": 1})",
                              "s.json");
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(s.curves[1].name, "b");
  EXPECT_EQ(s.curves[1].points[1], Vec3(0, 2, 0));
  const std::string e =
      error_of(std::string(R"({"patchlab": 1, "curves": [)") + kGoodCurve + "," + kBadCurve + "]}");
  EXPECT_NE(e.find("curves[1].points"), std::string::npos) << e;
}

TEST(StreamedCurves, ABadCurveIsReportedAfterWhatComesFirst) {
  const std::string bad = std::string(R"("curves": [)") + kBadCurve + "]";
  // A syntax error after the curve.
  EXPECT_NE(error_of("{" + bad + R"(, "patchlab": 1 ,})").find("invalid JSON"), std::string::npos);
  // The version, given after the curves.
  EXPECT_NE(error_of("{" + bad + R"(, "patchlab": 2})").find("unsupported format version"),
            std::string::npos);
  // An unknown top-level key.
  EXPECT_NE(error_of("{" + bad + R"(, "patchlab": 1, "extra": 0})").find("extra"),
            std::string::npos);
  // A bad patch.
  EXPECT_NE(error_of("{" + bad + R"(, "patchlab": 1, "patches": [{"type": "nope"}]})")
                .find("unknown patch type"),
            std::string::npos);
  // The first of two bad curves.
  const std::string two =
      std::string(R"({"patchlab": 1, "curves": [)") + kBadCurve + "," + kBadCurve + "]}";
  EXPECT_NE(error_of(two).find("curves[0]"), std::string::npos) << error_of(two);
  // A duplicate "curves" key is still one.
  EXPECT_NE(error_of("{" + bad + R"(, "patchlab": 1, "curves": []})").find("duplicate key"),
            std::string::npos);
}

TEST(StreamedCurves, CurvesThatAreNotAnArrayOrHoldNonObjects) {
  EXPECT_NE(error_of(R"({"patchlab": 1, "curves": {"a": 1}})").find("expected an array"),
            std::string::npos);
  const std::string e = error_of(R"({"patchlab": 1, "curves": [3]})");
  EXPECT_NE(e.find("curves[0]"), std::string::npos) << e;
  EXPECT_NE(e.find("expected an object"), std::string::npos) << e;
  EXPECT_TRUE(parse_scene(R"({"patchlab": 1, "curves": []})", "s.json").curves.empty());
}

}  // namespace
}  // namespace pl
