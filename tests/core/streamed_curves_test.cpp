// The reader takes a scene's curves one by one as the parser meets them (their JSON is not kept).
// Its errors must still come in the order of a reader that parsed the whole file first: a syntax
// error anywhere, then the top level, network and patches, then the first bad curve.
#include <gtest/gtest.h>

#include <string>

#include "core/base/data_error.hpp"
#include "core/io/curve_codec.hpp"
#include "core/io/json_node.hpp"
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

// The scene's first curve read the plain way: the whole document parsed to JSON, the curve read
// from its node, with the message that path gives.
std::string plain_read(const std::string& text, std::vector<Vec3>* points) {
  try {
    const nlohmann::json doc = parse_json(text, "s.json");
    *points = read_curve(JsonNode(doc.at("curves").at(0), "s.json", "curves[0]")).points;
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

// A curve's points are packed by the parser (no JSON per point) while they are plain [x, y, z]
// numbers; any other entry must be reported exactly as the plain reader reports it.
TEST(StreamedCurves, PackedPointsGiveThePointsAndTheMessagesOfThePlainReader) {
  const std::vector<std::string> cases = {
      R"([[0, 0, 0], [1, 2.5, -3], [4, 1e-300, 18446744073709551615]])",  // valid, every number
                                                                          // kind
      R"([[0, 0, 0], [1, 0]])", R"([[0, 0, 0], [1, 0, 0, 0]])", R"([[0, 0, 0], [1, "a", 0]])",
      R"([[0, 0, 0], [1, null, 0]])", R"([[0, 0, 0], [1, true, 0]])",
      R"([[0, 0, 0], [1, 1e300, 0]])", R"([[0, 0, 0], [-1e300, 0, 0], [1, 0, 0]])",
      R"([[0, 0, 0], 5])", R"([3, [0, 0, 0]])", R"([[0, 0, 0], [[1], 0, 0]])",
      R"([[0, 0, 0], {"x": 1}])", R"([[0, 0, 0], []])", R"([])", R"([[0, 0, 0]])",
      R"([[0, 0, 0], [1, 0, 1e999]])",  // overflows in the parser: located there
      R"([[0, 0, 0], [1, 0, ]])",       // a syntax error
  };
  for (const std::string& points : cases) {
    const std::string text =
        R"({"patchlab": 1, "curves": [{"type": "bezier", "points": )" + points + "}]}";
    std::vector<Vec3> plain_points;
    const std::string plain = plain_read(text, &plain_points);
    std::string streamed;
    std::vector<Vec3> streamed_points;
    try {
      streamed_points = parse_scene(text, "s.json").curves.at(0).points;
    } catch (const DataError& e) {
      streamed = e.what();
    }
    EXPECT_EQ(streamed, plain) << points;
    EXPECT_EQ(streamed_points, plain_points) << points;
    if (points == cases[0]) {
      ASSERT_EQ(streamed_points.size(), 3u);
      EXPECT_EQ(streamed_points[1], Vec3(1, 2.5, -3));
      EXPECT_EQ(streamed_points[2], Vec3(4, 1e-300, 18446744073709551615.0));
    }
  }
}

// Only a curve's own "points" are packed: a Hermite curve's tangents, and points elsewhere, are
// read as before, and a curve after a packed one starts afresh.
TEST(StreamedCurves, PackingIsPerCurveAndPerKey) {
  const Scene s = parse_scene(R"({"patchlab": 1, "curves": [
      {"type": "hermite", "points": [[0, 0, 0], [1, 0, 0]], "tangents": [[1, 1, 0], [1, -1, 0]]},
      {"type": "bezier", "points": [[0, 0, 0], [0, 1, 0], [0, 1, 1]]}]})",
                              "s.json");
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(s.curves[0].points, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}));
  EXPECT_EQ(s.curves[0].tangents, (std::vector<Vec3>{{1, 1, 0}, {1, -1, 0}}));
  EXPECT_EQ(s.curves[1].points, (std::vector<Vec3>{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}}));
  // A second "points" key in one curve is still a duplicate.
  const std::string e = error_of(
      R"({"patchlab": 1, "curves": [{"type": "bezier", "points": [[0,0,0],[1,0,0]], "points": []}]})");
  EXPECT_NE(e.find("curves[0].points: duplicate key"), std::string::npos) << e;
}

}  // namespace
}  // namespace pl
