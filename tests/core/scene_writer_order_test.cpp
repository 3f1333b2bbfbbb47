// The scene writer keeps the key order of the shipped samples (the documented order): every
// sample, read and written again, has the same keys in the same order and the same values, so a
// saved file's diff against a sample shows the edit, not a reordering. (Number spelling and
// indentation vary between the hand-written samples and are not compared.)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "core/io/scene_io.hpp"

namespace pl {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

using Ordered = nlohmann::ordered_json;

// Where two documents differ in structure, key order or value ("" when they agree). Numbers
// compare as doubles, exactly: 0 and 0.0 are the same number.
std::string difference(const Ordered& a, const Ordered& b, const std::string& path) {
  if (a.is_number() && b.is_number())
    return a.get<double>() == b.get<double>() ? "" : path + ": " + a.dump() + " vs " + b.dump();
  if (a.type() != b.type()) return path + ": " + a.type_name() + " vs " + b.type_name();
  if (a.is_object()) {
    std::vector<std::string> ka, kb;
    for (auto it = a.begin(); it != a.end(); ++it) ka.push_back(it.key());
    for (auto it = b.begin(); it != b.end(); ++it) kb.push_back(it.key());
    if (ka != kb) return path + ": keys " + Ordered(ka).dump() + " vs " + Ordered(kb).dump();
    for (const std::string& k : ka)
      if (auto d = difference(a.at(k), b.at(k), path + "." + k); !d.empty()) return d;
    return "";
  }
  if (a.is_array()) {
    if (a.size() != b.size())
      return path + ": " + std::to_string(a.size()) + " items vs " + std::to_string(b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      if (auto d = difference(a[i], b[i], path + "[" + std::to_string(i) + "]"); !d.empty())
        return d;
    return "";
  }
  return a == b ? "" : path + ": " + a.dump() + " vs " + b.dump();
}

TEST(SceneWriterOrder, EveryAssetLoadsAndSavesWithItsKeyOrder) {
  const fs::path assets = fs::path(PATCHLAB_SOURCE_DIR) / "assets";
  ASSERT_TRUE(fs::is_directory(assets)) << assets;
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(assets)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const Ordered file = Ordered::parse(slurp(entry.path()));
    const std::string written = scene_to_json(read_scene(entry.path()));
    EXPECT_EQ(difference(file, Ordered::parse(written), "$"), "") << entry.path();
    // Saving again changes nothing at all.
    EXPECT_EQ(scene_to_json(parse_scene(written, "again.json")), written) << entry.path();
  }
  EXPECT_GE(files, 16);  // the samples of the README and docs
}

TEST(SceneWriterOrder, KeysFollowTheDocumentedOrder) {
  // Every optional key present, to pin the order of those no sample uses.
  const std::string text = R"({
 "patchlab": 1,
 "name": "all keys",
 "network": {
  "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0.5]],
  "normals": [null, [0, 0, 1], null],
  "edges": [
   {"v": [0, 1], "handles": [[0.25, 0, 0], [0.75, 0, 0]], "name": "e0"},
   {"v": [1, 2], "handles": [[0.75, 0.25, 0], [0.25, 0.75, 0.5]], "name": "e1"},
   {"v": [2, 0], "handles": [[0, 0.75, 0.5], [0, 0.25, 0]], "name": "e2"}
  ],
  "faces": [{"loop": [0, 1, 2], "scheme": "gregory", "name": "tri"}]
 },
 "patches": [{"type": "bezier", "name": "p", "degree": [1, 1],
              "points": [[0, 0, 2], [0, 1, 2], [1, 0, 2], [1, 1, 2.5]]}],
 "view": {"b": 1, "a": 2}
})";
  const std::string out = scene_to_json(parse_scene(text, "all.json"));
  auto at = [&](const std::string& key) {
    const auto p = out.find("\"" + key + "\"");
    EXPECT_NE(p, std::string::npos) << key;
    return p;
  };
  EXPECT_LT(at("patchlab"), at("name"));
  EXPECT_LT(at("name"), at("network"));
  EXPECT_LT(at("network"), at("patches"));
  EXPECT_LT(at("patches"), at("view"));
  EXPECT_LT(at("vertices"), at("normals"));
  EXPECT_LT(at("normals"), at("edges"));
  EXPECT_LT(at("edges"), at("faces"));
  EXPECT_LT(at("v"), at("handles"));
  EXPECT_LT(out.find("\"handles\""), out.find("\"e0\""));
  EXPECT_LT(at("loop"), at("scheme"));
  EXPECT_LT(at("scheme"), out.find("\"tri\""));
  EXPECT_LT(at("type"), out.find("\"p\""));
  EXPECT_LT(out.find("\"p\""), at("degree"));
  EXPECT_LT(at("degree"), out.find("\"points\""));
  EXPECT_EQ(scene_to_json(parse_scene(out, "again.json")), out);
}

TEST(SceneWriterOrder, NumbersReadBackBitForBit) {
  Scene s;
  s.network = Network{};
  const double values[] = {0.0,  -0.0,   1.0, -3.0, 0.1, 1e-300, 123456789.0, 9007199254740993.0,
                           1e22, -2.5e-7};
  for (double v : values) s.network->vertices.push_back(Vec3(v, -v, v * 0.5));
  const Scene back = parse_scene(scene_to_json(s), "numbers.json");
  ASSERT_EQ(back.network->vertices.size(), s.network->vertices.size());
  for (std::size_t i = 0; i < s.network->vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double a = s.network->vertices[i][k], b = back.network->vertices[i][k];
      EXPECT_EQ(a, b) << i << " " << k;
      EXPECT_EQ(std::signbit(a), std::signbit(b)) << i << " " << k;
    }
}

// One curve bigger than the writer's pieces (about a megabyte): its arrays are written item by
// item, flushed within the curve; the file must still be one dump of the whole document.
TEST(SceneWriterOrder, ACurveBiggerThanAPieceIsWrittenWhole) {
  Scene s;
  SceneCurve c;
  c.type = CurveType::Nurbs;
  c.degree = 3;
  const int n = 60000;
  for (int i = 0; i < n; ++i) {
    c.points.emplace_back(i * 0.1, std::sin(i * 0.3), -1e-7 * i);
    c.weights.push_back(1 + 0.5 * std::cos(i * 0.7));
  }
  for (int i = 0; i < n + 4; ++i) c.knots.push_back(std::clamp(i - 3, 0, n - 3) / 7.0);
  s.curves.push_back(c);
  const fs::path file = fs::temp_directory_path() / "patchlab-writer-big-curve-test.json";
  write_scene(file, s);
  const std::string text = slurp(file);
  EXPECT_GT(text.size(), 4u << 20);
  EXPECT_EQ(Ordered::parse(text).dump(1) + "\n", text);
  EXPECT_EQ(text, scene_to_json(s));
  const Scene back = read_scene(file);
  ASSERT_EQ(back.curves.size(), 1u);
  EXPECT_EQ(back.curves[0].points, c.points);
  EXPECT_EQ(back.curves[0].weights, c.weights);
  EXPECT_EQ(back.curves[0].knots, c.knots);
  fs::remove(file);
}

// The writer writes the curves one at a time, beside the rest of the document dumped at once: the
// text must be exactly what one dump of the whole document gives (parsed and dumped again here),
// with every curve type, with and without the keys before and after "curves", and in a file.
TEST(SceneWriterOrder, CurvesWrittenOneAtATimeGiveTheWholeDocumentsText) {
  const fs::path assets = fs::path(PATCHLAB_SOURCE_DIR) / "assets";
  std::vector<Scene> scenes;
  for (const auto& entry : fs::recursive_directory_iterator(assets))
    if (entry.path().extension() == ".json") scenes.push_back(read_scene(entry.path()));
  Scene all = read_scene(assets / "curves" / "interpolating-hermite-bezier.json");
  for (const char* name : {"nurbs-circle-and-conics.json", "bspline-knot-multiplicity.json"})
    for (const SceneCurve& c : read_scene(assets / "curves" / name).curves) all.curves.push_back(c);
  all.name = "curves \"and\" more\n \"curves\": []";  // the writer's own marker, as text
  all.view_json = R"({"b": [1, 2], "a": {"c": null}})";
  all.network = read_scene(assets / "default.json").network;
  scenes.push_back(all);
  Scene one;
  one.curves.push_back(all.curves.front());
  scenes.push_back(one);
  scenes.push_back(Scene{});
  int with_curves = 0;
  for (const Scene& s : scenes) {
    with_curves += !s.curves.empty();
    const std::string text = scene_to_json(s);
    EXPECT_EQ(Ordered::parse(text).dump(1) + "\n", text) << s.name;
  }
  EXPECT_GE(with_curves, 6);
  const fs::path file = fs::temp_directory_path() / "patchlab-writer-pieces-test.json";
  write_scene(file, all);
  EXPECT_EQ(slurp(file), scene_to_json(all));
  fs::remove(file);
}

}  // namespace
}  // namespace pl
