// OBJ polylines as free curves: each `l` line a degree-1 B-spline through its vertices (checked
// by evaluating it at its knots and between them), names from `o`/`g`, and every malformed input
// refused with the file and the line named.
#include "core/io/obj_curves.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/base/data_error.hpp"

namespace pl {
namespace {

class ObjFiles : public ::testing::Test {
 protected:
  ObjFiles() {
    std::random_device rd;
    dir_ = std::filesystem::temp_directory_path() / ("patchlab-obj-" + std::to_string(rd()));
    std::filesystem::create_directories(dir_);
  }
  ~ObjFiles() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  // The DataError's text for reading `text`, or "" if it reads.
  std::string error_of(const std::string& text) {
    try {
      read_obj_curves(write("bad.obj", text));
    } catch (const DataError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
};

TEST_F(ObjFiles, LinesBecomePolylineCurves) {
  const auto file = write("wire.obj",
                          "# a wire and a face\n"
                          "o frame\n"
                          "v 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 1.5\n"
                          "vt 0 0\n"
                          "l 1 2 3/1 4\n"
                          "f 1 2 3\n"
                          "g second\n"
                          "l -1 -4\n");
  const ObjCurves obj = read_obj_curves(file);
  ASSERT_EQ(obj.curves.size(), 2u);
  EXPECT_EQ(obj.faces_passed_over, 1u);
  const SceneCurve& a = obj.curves[0];
  EXPECT_EQ(a.name, "frame line 8");
  EXPECT_EQ(obj.curves[1].name, "second line 11");
  EXPECT_EQ(a.type, CurveType::BSpline);
  EXPECT_EQ(a.degree, 1);
  ASSERT_NO_THROW(validate_curve(a));
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 1.5}};
  ASSERT_EQ(a.points, corners);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(evaluate(a, k).p, corners[k]);  // through each vertex
  for (int k = 0; k < 3; ++k)                                           // straight between them
    EXPECT_LT(glm::length(evaluate(a, k + 0.25).p - (0.75 * corners[k] + 0.25 * corners[k + 1])),
              1e-15);
  EXPECT_EQ(obj.curves[1].points, (std::vector<Vec3>{corners[3], corners[0]}));
}

TEST_F(ObjFiles, MalformedInputIsRefusedWithItsLine) {
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nl 1 3\n").find("line 3: vertex 3 does not exist"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 zero\n").find("line 1: \"zero\" is not a number"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 nan\n").find("line 1"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 1e300\nv 0 0 0\nl 1 2\n").find("line 1: coordinate"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nl 1\n").find("line 2: a line needs two points"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 1 1\nl 1 2 2\n").find("line 3: the line repeats a point"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nl 1 x\n").find("line 3: \"x\" is not a vertex index"),
            std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("faces are not curves: 1"),
            std::string::npos);
  EXPECT_NE(error_of("").find("no polyline"), std::string::npos);
  EXPECT_THROW(read_obj_curves(dir_ / "missing.obj"), DataError);
}

}  // namespace
}  // namespace pl
