// What every document command must do: leave a scene the reader accepts, undo and redo bit for
// bit, and change nothing when it refuses.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "app/document/document.hpp"
#include "cli_test_util.hpp"
#include "core/io/scene_io.hpp"

namespace pl::test {

// Bit patterns, not values: -0 and 0 differ, NaNs compare.
inline bool same_bits(const Vec3& a, const Vec3& b) {
  return std::memcmp(&a, &b, sizeof(Vec3)) == 0;
}

inline bool same_bits(const Network& a, const Network& b) {
  if (a.vertices.size() != b.vertices.size() || a.normals.size() != b.normals.size() ||
      a.edges.size() != b.edges.size() || a.faces != b.faces)
    return false;
  for (std::size_t v = 0; v < a.vertices.size(); ++v)
    if (!same_bits(a.vertices[v], b.vertices[v])) return false;
  for (std::size_t v = 0; v < a.normals.size(); ++v)
    if (a.normals[v].has_value() != b.normals[v].has_value() ||
        (a.normals[v] && !same_bits(*a.normals[v], *b.normals[v])))
      return false;
  for (std::size_t e = 0; e < a.edges.size(); ++e)
    if (a.edges[e].v != b.edges[e].v || a.edges[e].name != b.edges[e].name ||
        !same_bits(a.edges[e].handles[0], b.edges[e].handles[0]) ||
        !same_bits(a.edges[e].handles[1], b.edges[e].handles[1]))
      return false;
  return true;
}

inline bool same_bits(const Scene& a, const Scene& b) {
  if (a.network.has_value() != b.network.has_value()) return false;
  if (a.network && !same_bits(*a.network, *b.network)) return false;
  if (a.patches.size() != b.patches.size()) return false;
  for (std::size_t i = 0; i < a.patches.size(); ++i) {
    const auto &pa = a.patches[i].patch->control_points(),
               &pb = b.patches[i].patch->control_points();
    if (pa.size() != pb.size() || std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(Vec3)) != 0)
      return false;
  }
  return scene_to_json(a) == scene_to_json(b);
}

// Executes the command and checks: one undo step more, the written file is read back as the
// same scene, undo gives the scene before and redo the scene after, bit for bit. Returns the
// label.
inline std::string expect_good_command(Document& doc, std::unique_ptr<Command> command) {
  const Scene before = doc.scene();
  const std::string undo_before = doc.undo_label();
  const std::string label = doc.execute(std::move(command));
  const Scene after = doc.scene();
  EXPECT_TRUE(doc.can_undo());
  EXPECT_EQ(doc.undo_label(), label);
  {
    TempDir dir;
    write_scene(dir / "scene.json", after);
    Scene back;
    EXPECT_NO_THROW(back = read_scene(dir / "scene.json")) << label;
    EXPECT_TRUE(same_bits(back, after)) << label << ": the file does not read back as the scene";
  }
  EXPECT_TRUE(doc.undo());
  EXPECT_TRUE(same_bits(doc.scene(), before)) << label << ": undo";
  EXPECT_EQ(doc.undo_label(), undo_before);
  EXPECT_TRUE(doc.redo());
  EXPECT_TRUE(same_bits(doc.scene(), after)) << label << ": redo";
  return label;
}

// The command is refused with a message containing `why`, and the document is unchanged.
inline void expect_refused(Document& doc, std::unique_ptr<Command> command,
                           const std::string& why) {
  const Scene before = doc.scene();
  const uint64_t revision = doc.revision();
  const std::string undo = doc.undo_label();
  const bool can_redo = doc.can_redo();
  try {
    doc.execute(std::move(command));
    ADD_FAILURE() << "expected a refusal containing \"" << why << "\"";
  } catch (const EditRefused& e) {
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
  EXPECT_TRUE(same_bits(doc.scene(), before));
  EXPECT_EQ(doc.revision(), revision);
  EXPECT_EQ(doc.undo_label(), undo);
  EXPECT_EQ(doc.can_redo(), can_redo);
}

}  // namespace pl::test
