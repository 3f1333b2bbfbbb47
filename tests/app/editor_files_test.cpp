// The editor's files: Save As refuses or corrects the extension, a .gbp is saved back as a .gbp
// (or Save As is offered in its folder with its name), the flip command and its action, and the
// STEP/IGES export on a worker thread.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <thread>

#include "app/document/network_commands.hpp"
#include "app/document/scene_commands.hpp"
#include "app/document/scene_file.hpp"
#include "app/editor/logic/cad_export_job.hpp"
#include "app/editor/logic/document_session.hpp"
#include "app/editor/logic/file_listing.hpp"
#include "app/editor/logic/patch_actions.hpp"
#include "cli_test_util.hpp"
#include "core/base/data_error.hpp"
#include "core/io/gbp_io.hpp"
#include "core/io/scene_io.hpp"
#include "core/patch/bezier_patch.hpp"
#include "core/patch/flip_orientation.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

const fs::path kAssets = fs::path(PATCHLAB_SOURCE_DIR) / "assets";

// A GB quadrilateral of degree 3 over a gently curved dome.
GBPatch gb_dome() {
  const int n = 4, d = 3;
  std::vector<Vec3> p(GBPatch::point_count(n, d));
  const GBPatch shape(n, d, p);
  for (int k = 0; k < shape.layers(); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j) {
        const Vec2 a = shape.polygon().vertex(i - 1), b = shape.polygon().vertex(i);
        const Vec2 q = (a + (double(j) / d) * (b - a)) * (1.0 - 0.8 * k / d);
        p[shape.index(i, j, k)] = {2 * q.x, 2 * q.y, 0.4 * k + 0.1 * q.x};
      }
  p[0] = {0, 0, 0.8};
  return GBPatch(n, d, std::move(p));
}

TEST(EditorFiles, SaveAsRefusesAnUnknownExtensionAndCorrectsAMissingOne) {
  TempDir tmp;
  DocumentSession session({kAssets});
  session.open(kAssets / "default.json");  // an untitled copy
  session.doc().execute(std::make_unique<MovePointsCommand>(
      std::vector<PointRef>{PointRef::vertex(2)}, std::vector<Vec3>{Vec3(1, 1, 0.9)}));
  // A typo: a file Open would never list. Refused, nothing written, still untitled and dirty.
  for (const char* bad : {"part.jsonn", "part.txt", "part.JSON", "part.json.bak"}) {
    try {
      session.save_as(tmp / bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const DataError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(".json"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(tmp / bad)) << bad;
  }
  EXPECT_TRUE(session.untitled());
  EXPECT_TRUE(session.doc().dirty());
  // No extension: ".json" is added, and the file reads back.
  const fs::path written = session.save_as(tmp / "part");
  EXPECT_EQ(written, tmp / "part.json");
  EXPECT_FALSE(fs::exists(tmp / "part"));
  EXPECT_EQ(session.title(), "part.json");
  EXPECT_EQ(read_scene(written).network->vertices[2], Vec3(1, 1, 0.9));
  // The browser says why before anything is tried.
  EXPECT_NE(extension_problem(tmp / "x.jsonn", {".json", ".gbp"}).find("\".jsonn\""),
            std::string::npos);
  EXPECT_EQ(extension_problem(tmp / "x.json", {".json", ".gbp"}), "");
  EXPECT_EQ(extension_problem(tmp / "x.GBP", {".json", ".gbp"}), "");
  EXPECT_NE(extension_problem(tmp / "x", {".json"}), "");
}

TEST(EditorFiles, AGbpIsSavedBackAsAGbp) {
  TempDir tmp;
  const GBPatch dome = gb_dome();
  write_gbp(tmp / "dome.gbp", dome);
  DocumentSession session({kAssets});
  session.open(tmp / "dome.gbp");
  EXPECT_FALSE(session.untitled());
  EXPECT_EQ(session.title(), "dome.gbp");
  // Flip it (the scene stays one GB patch) and Ctrl+S: the same file, still a .gbp.
  session.doc().execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{0}));
  EXPECT_EQ(session.title(), "dome.gbp *");
  ASSERT_TRUE(session.save());
  EXPECT_FALSE(session.doc().dirty());
  const GBPatch back = read_gbp(tmp / "dome.gbp");
  const auto& flipped = dynamic_cast<const GBPatch&>(*session.doc().scene().patches[0].patch);
  EXPECT_EQ(test::slurp(tmp / "dome.gbp"), gbp_to_text(flipped));
  EXPECT_EQ(back.control_points(), flipped.control_points());
  EXPECT_NE(back.control_points(), dome.control_points());
  // Save As suggests its own folder and name.
  EXPECT_EQ(session.save_as_suggestion().dir, (tmp / "dome.gbp").parent_path());
  EXPECT_EQ(session.save_as_suggestion().name, "dome.gbp");
}

// Ctrl+S on a .gbp read from elsewhere (transfinite's cagd86) after moving one point: the file
// differs from the original on that point's line only (numbers keep their shortest spelling),
// and every other point reads back as the same double.
TEST(EditorFiles, SavingAGbpBackChangesOnlyTheEditedPointsLine) {
  TempDir tmp;
  const fs::path original = fs::path(PATCHLAB_TEST_DATA_DIR) / "gb" / "cagd86.gbp";
  ASSERT_TRUE(fs::exists(original)) << original;
  fs::copy_file(original, tmp / "cagd86.gbp");
  DocumentSession session({kAssets});
  session.open(tmp / "cagd86.gbp");
  const auto& before = dynamic_cast<const GBPatch&>(*session.doc().scene().patches[0].patch);
  const std::vector<Vec3> points = before.control_points();
  const int moved = 7;
  session.doc().execute(
      std::make_unique<MovePointsCommand>(std::vector<PointRef>{PointRef::patch_point(0, moved)},
                                          std::vector<Vec3>{points[moved] + Vec3(1.5, -2.25, 0)}));
  ASSERT_TRUE(session.save());
  auto lines = [](const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  };
  const std::vector<std::string> was = lines(test::slurp(original)),
                                 now = lines(test::slurp(tmp / "cagd86.gbp"));
  ASSERT_EQ(was.size(), now.size());
  for (std::size_t i = 0; i < was.size(); ++i) {
    if (i == std::size_t(moved) + 1) {  // after the "n d" line
      EXPECT_NE(was[i], now[i]);
    } else {
      EXPECT_EQ(was[i], now[i]) << "line " << i + 1;
    }
  }
  const GBPatch back = read_gbp(tmp / "cagd86.gbp");
  for (std::size_t k = 0; k < points.size(); ++k)
    if (int(k) != moved) {
      EXPECT_EQ(back.control_points()[k], points[k]) << k;
    }
  EXPECT_EQ(back.control_points()[moved], points[moved] + Vec3(1.5, -2.25, 0));
}

TEST(EditorFiles, AGbpThatNoLongerFitsAsksForASceneFileInItsFolder) {
  TempDir tmp;
  write_gbp(tmp / "dome.gbp", gb_dome());
  const std::string before = test::slurp(tmp / "dome.gbp");
  DocumentSession session({kAssets});
  session.open(tmp / "dome.gbp");
  // A network vertex added: a .gbp cannot hold that.
  session.doc().execute(std::make_unique<AddVertexCommand>(Vec3(3, 0, 0)));
  EXPECT_FALSE(fits_gbp(session.doc().scene()));
  EXPECT_FALSE(session.save());  // Save As is needed; nothing written
  EXPECT_EQ(test::slurp(tmp / "dome.gbp"), before);
  const DocumentSession::Suggestion s = session.save_as_suggestion();
  EXPECT_EQ(s.dir, (tmp / "dome.gbp").parent_path());
  EXPECT_EQ(s.name, "dome.json");
  EXPECT_THROW(session.save_as(tmp / "other.gbp"), DataError);
  EXPECT_FALSE(fs::exists(tmp / "other.gbp"));
  session.save_as(tmp / s.name);
  EXPECT_EQ(read_scene(tmp / "dome.json").network->vertices.size(), 1u);
  EXPECT_EQ(session.title(), "dome.json");
}

TEST(EditorFiles, UntitledCopiesSuggestTheirOriginsName) {
  DocumentSession session({kAssets});
  session.open(kAssets / "default.json");
  EXPECT_TRUE(session.save_as_suggestion().dir.empty());  // the editor picks a folder
  EXPECT_EQ(session.save_as_suggestion().name, "default.json");
  session.new_scene();
  EXPECT_EQ(session.save_as_suggestion().name, "");
}

TEST(EditorFiles, SaveSceneFileWritesWhatLoadInputReads) {
  TempDir tmp;
  Scene one;
  one.patches.push_back({"", std::make_shared<GBPatch>(gb_dome())});
  save_scene_file(tmp / "a.gbp", one);
  save_scene_file(tmp / "a.json", one);
  EXPECT_EQ(read_gbp(tmp / "a.gbp").control_points(), one.patches[0].patch->control_points());
  EXPECT_EQ(scene_to_json(read_scene(tmp / "a.json")), scene_to_json(one));
  const Scene net = read_scene(kAssets / "default.json");
  EXPECT_THROW(save_scene_file(tmp / "b.gbp", net), DataError);
  EXPECT_THROW(save_scene_file(tmp / "b.stl", net), DataError);
  EXPECT_FALSE(fs::exists(tmp / "b.gbp"));
  EXPECT_FALSE(fs::exists(tmp / "b.stl"));
}

TEST(EditorFlip, FlipsAPatchAndUndoesBitForBit) {
  Document doc(read_scene(kAssets / "bezier-saddle.json"));
  ASSERT_EQ(doc.scene().patches.size(), 1u);
  const std::string original = scene_to_json(doc.scene());
  const std::shared_ptr<Patch> before = doc.scene().patches[0].patch;
  doc.execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{0}));
  const Patch& after = *doc.scene().patches[0].patch;
  EXPECT_EQ(doc.undo_label(), "flip patch 0");
  // The same surface with the normal reversed: at the reflected parameter (u <-> v).
  for (double u : {0.1, 0.5, 0.8})
    for (double v : {0.2, 0.6}) {
      const SurfaceJet a = before->evaluate(Vec2(u, v)), b = after.evaluate(Vec2(v, u));
      EXPECT_LT(glm::length(a.p - b.p), 1e-12);
      const Vec3 na = glm::normalize(glm::cross(a.su, a.sv)),
                 nb = glm::normalize(glm::cross(b.su, b.sv));
      EXPECT_LT(glm::length(na + nb), 1e-12);
    }
  const std::string flipped = scene_to_json(doc.scene());
  EXPECT_NE(flipped, original);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), original);
  EXPECT_EQ(doc.scene().patches[0].patch, before);  // the very object, untouched
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(scene_to_json(doc.scene()), flipped);
  // Twice is the identity for the square patches.
  doc.execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{0}));
  EXPECT_EQ(scene_to_json(doc.scene()), original);
}

TEST(EditorFlip, RefusedForCompositePatchesAndMissingOnes) {
  Document doc(read_scene(kAssets / "classic" / "pair-join.json"));
  const std::string original = scene_to_json(doc.scene());
  ASSERT_FALSE(can_flip_orientation(*doc.scene().patches[0].patch));
  EXPECT_THROW(doc.execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{0})), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{7})), EditRefused);
  EXPECT_THROW(doc.execute(std::make_unique<FlipPatchesCommand>(std::vector<int>{})), EditRefused);
  EXPECT_EQ(scene_to_json(doc.scene()), original);
  EXPECT_FALSE(doc.can_undo());
}

TEST(EditorFlip, TheActionFlipsTheOnlyPatchAndSelectedPointsFollow) {
  Document doc(read_scene(kAssets / "bezier-saddle.json"));
  Selection sel;
  ActionRegistry actions;
  std::string said;
  add_patch_actions(actions, doc, sel, [&](const std::string& m) { said = m; });
  const Action* flip = actions.find("patch.flip");
  ASSERT_TRUE(flip);
  EXPECT_EQ(patches_to_flip(doc.scene(), sel), std::vector<int>{0});  // the only one
  EXPECT_TRUE(actions.is_enabled(*flip));
  // A selected control point stays on the same point of space.
  const PointRef p = PointRef::patch_point(0, 1);
  sel.set({SelectionItem::of_point(p)});
  const Vec3 where = point_position(doc.scene(), p);
  actions.run("patch.flip");
  EXPECT_EQ(said, "flip patch 0");
  ASSERT_EQ(sel.points().size(), 1u);
  EXPECT_NE(sel.points()[0], p);  // point 1 moved in the order (u <-> v)
  EXPECT_EQ(point_position(doc.scene(), sel.points()[0]), where);
  // Not offered for a network scene with nothing selected, nor for a composite patch.
  Document net(read_scene(kAssets / "default.json"));
  Selection none;
  EXPECT_TRUE(patches_to_flip(net.scene(), none).empty());
  Document pair(read_scene(kAssets / "classic" / "pair-join.json"));
  ActionRegistry pair_actions;
  add_patch_actions(pair_actions, pair, none, nullptr);
  EXPECT_FALSE(pair_actions.is_enabled(*pair_actions.find("patch.flip")));
}

TEST(EditorRecovery, RecoveredWorkIsOneUndoStepOnTheSavedFile) {
  Document doc(read_scene(kAssets / "default.json"), "/somewhere/scene.json");
  const std::string saved = scene_to_json(doc.scene());
  Scene recovered = doc.scene();
  recovered.network->vertices[2].z += 0.25;
  doc.execute(std::make_unique<ReplaceSceneCommand>(recovered, "recovered unsaved changes"));
  EXPECT_TRUE(doc.dirty());
  EXPECT_EQ(scene_to_json(doc.scene()), scene_to_json(recovered));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(scene_to_json(doc.scene()), saved);
}

// Polls the job until it has finished (a generous bound: the machine may be busy).
CadExportJob::Result wait_for(CadExportJob& job) {
  for (int i = 0; i < 6000; ++i) {
    if (auto r = job.poll()) return *r;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ADD_FAILURE() << "the export did not finish in 120 s";
  return {};
}

TEST(EditorCadExport, ExportsOnAWorkerAndReportsOrFails) {
  TempDir tmp;
  const Scene scene = read_scene(kAssets / "default.json");
  CadExportJob job;
  EXPECT_FALSE(job.running());
  EXPECT_FALSE(job.poll());
  bool finished = false;
  ASSERT_TRUE(job.start(scene, tmp / "default.step", {}, [&] { finished = true; }));
  EXPECT_TRUE(job.running());
  EXPECT_FALSE(job.start(scene, tmp / "other.step", {}));  // one at a time
  const CadExportJob::Result r = wait_for(job);
  EXPECT_TRUE(finished);
  EXPECT_FALSE(job.running());
  EXPECT_TRUE(r.ok) << r.text;
  EXPECT_EQ(r.target, tmp / "default.step");
  EXPECT_TRUE(fs::file_size(tmp / "default.step") > 0);
  EXPECT_FALSE(fs::exists(tmp / "other.step"));
  // The report the CLI prints for the same export (written again to the same file).
  CadExportOptions o;
  EXPECT_EQ(r.text, cad_report_text(export_cad(scene, tmp / "default.step", o)));
  // A folder that does not exist: the message names the target, nothing is written.
  ASSERT_TRUE(job.start(scene, tmp / "missing" / "x.igs", {}));
  const CadExportJob::Result bad = wait_for(job);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.text.find("x.igs"), std::string::npos) << bad.text;
  EXPECT_FALSE(fs::exists(tmp / "missing"));
}

}  // namespace
}  // namespace pl
