// The curve commands on a document: each one undo step, the operations leave the curve's points
// where they were, refusals change nothing, and a saved document's curve is what analyze reads.
#include "app/document/curve_commands.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/document/document.hpp"
#include "cli_test_util.hpp"
#include "core/io/scene_io.hpp"
#include "curve_test_util.hpp"

namespace pl::test {
namespace {

TEST(CurveCommands, BuildEditSaveAnalyze) {
  TempDir dir;
  Document doc;
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::BSpline, six_points()));
  ASSERT_EQ(doc.scene().curves.size(), 1u);
  EXPECT_EQ(doc.scene().curves[0].degree, 3);
  const SceneCurve before = doc.scene().curves[0];
  doc.execute(std::make_unique<CurveOperationCommand>(
      0, CurveOperationCommand::Operation::InsertKnot, 0.4));
  EXPECT_EQ(doc.scene().curves[0].points.size(), 7u);
  EXPECT_LE(max_sample_difference(before, doc.scene().curves[0]), 1e-14 * 5);
  // A drag: a run of moves of one point is one undo step.
  const Scene before_drag = doc.scene();
  for (int k = 1; k <= 5; ++k)
    doc.execute(std::make_unique<MoveCurvePointCommand>(0, 3, Vec3(2.5, 1 + 0.1 * k, 0.2)));
  EXPECT_EQ(doc.scene().curves[0].points[3], Vec3(2.5, 1.5, 0.2));
  EXPECT_EQ(doc.undo_label(), "move curve 0 point 3");
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().curves[0].points, before_drag.curves[0].points);
  ASSERT_TRUE(doc.redo());
  const auto file = dir / "c.json";
  doc.save_as(file);
  const CliResult r = cli({"analyze", file.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["curves"].size(), 1u);
  EXPECT_EQ(j["curves"][0]["type"], "bspline");
  EXPECT_EQ(j["curves"][0]["control_points"], 7);
  EXPECT_TRUE(std::isfinite(j["curves"][0]["length"].get<double>()));
  EXPECT_TRUE(std::isfinite(j["curves"][0]["curvature"][1].get<double>()));
  EXPECT_EQ(j["curves"][0]["nonfinite_samples"], 0);
}

TEST(CurveCommands, OperationsKeepTheCurveAndRefusalsChangeNothing) {
  Document doc;
  doc.execute(std::make_unique<AddCurveCommand>(CurveType::Nurbs, six_points()));
  EXPECT_EQ(doc.execute(std::make_unique<SetCurveWeightCommand>(0, 2, 3.0)),
            "weight of curve 0 point 2");
  EXPECT_EQ(doc.scene().curves[0].weights[2], 3.0);
  const SceneCurve c = doc.scene().curves[0];
  doc.execute(
      std::make_unique<CurveOperationCommand>(0, CurveOperationCommand::Operation::ElevateDegree));
  EXPECT_EQ(doc.scene().curves[0].degree, 4);
  EXPECT_LE(max_sample_difference(c, doc.scene().curves[0]), 1e-14 * 5);
  doc.execute(
      std::make_unique<CurveOperationCommand>(0, CurveOperationCommand::Operation::Reverse));
  EXPECT_LE(glm::length(evaluate(doc.scene().curves[0], 0.0).p - c.points.back()), 1e-15);
  doc.execute(
      std::make_unique<CurveOperationCommand>(0, CurveOperationCommand::Operation::Split, 0.3));
  EXPECT_EQ(doc.scene().curves.size(), 2u);
  const uint64_t revision = doc.revision();
  const Scene kept = doc.scene();
  EXPECT_THROW(doc.execute(std::make_unique<SetCurveWeightCommand>(0, 1, 0.0)), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<SetCurveWeightCommand>(0, 1, -1.0)), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<CurveOperationCommand>(
                   0, CurveOperationCommand::Operation::Split, 5.0)),
               EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<MoveCurvePointCommand>(7, 0, Vec3(0))), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<MoveCurvePointCommand>(0, 99, Vec3(0))), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<SetCurveWeightCommand>(0, -1, 2.0)), EditRefused);
  EXPECT_THROW(
      doc.execute(std::make_unique<AddCurveCommand>(CurveType::Interpolating, six_points())),
      EditRefused);
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_EQ(scene_to_json(doc.scene()), scene_to_json(kept));
  // Undo all the way back: the scene has no curve.
  while (doc.undo()) {
  }
  EXPECT_TRUE(doc.scene().curves.empty());
}

TEST(CurveCommands, DeleteCurvesRemovesThemInOneStepAndRefusesAMissingOne) {
  Document doc;
  for (int k = 0; k < 4; ++k) {
    std::vector<Vec3> points = six_points();
    for (Vec3& p : points) p.z += k;  // four curves told apart by their height
    doc.execute(std::make_unique<AddCurveCommand>(CurveType::BSpline, points));
  }
  const std::vector<SceneCurve> before = doc.scene().curves;
  EXPECT_EQ(doc.execute(std::make_unique<DeleteCurvesCommand>(std::vector<int>{2, 0, 2})),
            "delete curves 0, 2");
  ASSERT_EQ(doc.scene().curves.size(), 2u);
  EXPECT_EQ(doc.scene().curves[0].points, before[1].points);
  EXPECT_EQ(doc.scene().curves[1].points, before[3].points);
  ASSERT_TRUE(doc.undo());
  ASSERT_EQ(doc.scene().curves.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(doc.scene().curves[k].points, before[k].points);
  const uint64_t revision = doc.revision();
  EXPECT_THROW(doc.execute(std::make_unique<DeleteCurvesCommand>(std::vector<int>{1, 4})),
               EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<DeleteCurvesCommand>(std::vector<int>{})), EditRefused);
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_EQ(doc.scene().curves.size(), 4u) << "a refusal deletes nothing";
}

}  // namespace
}  // namespace pl::test
