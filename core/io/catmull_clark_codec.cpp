// {"type": "catmull-clark", "vertices": [points], "faces": [[a, b, c, d], ...]}: a polygon control
// mesh (3 or more vertices a face), faces counter-clockwise seen from outside (see
// catmull_clark_patch.hpp).
#include <cstdio>

#include "core/io/patch_codec.hpp"
#include "core/patch/catmull_clark_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_catmull_clark(const JsonNode& node) {
  node.allow_only({"type", "name", "vertices", "faces"});
  const JsonNode vn = node.at("vertices");
  if (vn.items().size() > CatmullClarkLimit::kMaxVertices)
    vn.fail("a Catmull-Clark mesh has at most " + std::to_string(CatmullClarkLimit::kMaxVertices) +
            " vertices, this one has " + std::to_string(vn.items().size()));
  const std::vector<Vec3> vertices = vn.points();
  const JsonNode fn = node.at("faces");
  std::vector<std::vector<int>> faces;
  const auto items = fn.items();
  if (items.empty()) fn.fail("a Catmull-Clark mesh needs at least one face");
  for (const JsonNode& f : items) {
    std::vector<int> loop;
    const auto corners = f.items();
    if (corners.size() < 3)
      f.fail("a face needs at least 3 vertices, got " + std::to_string(corners.size()));
    if (corners.size() > std::size_t(CatmullClarkLimit::kMaxValence))
      f.fail("a face has at most " + std::to_string(CatmullClarkLimit::kMaxValence) +
             " vertices, this one has " + std::to_string(corners.size()));
    for (const JsonNode& v : corners) {
      const long long i = v.integer();
      if (i < 0 || i >= static_cast<long long>(vertices.size()))
        v.fail("vertex " + std::to_string(i) + " does not exist (" +
               std::to_string(vertices.size()) + " vertices)");
      loop.push_back(static_cast<int>(i));
    }
    faces.push_back(std::move(loop));
  }
  try {
    return std::make_unique<CatmullClarkPatch>(vertices, faces);
  } catch (const std::invalid_argument& e) {
    // A message about one face is located at it: "face 3 repeats vertex 0" at faces[3].
    const std::string what = e.what();
    std::size_t face = 0;
    if (std::sscanf(what.c_str(), "face %zu", &face) == 1 && face < items.size())
      items[face].fail(what);
    fn.fail(what);  // unused vertices, the mesh as a whole
  }
}

void write_catmull_clark(const Patch& patch, nlohmann::json& out) {
  const auto& cc = patch_ref<CatmullClarkPatch>(patch);
  out["vertices"] = points_json(cc.control_points());
  out["faces"] = cc.limit().faces();
}

}  // namespace

const PatchCodec kCatmullClarkCodec{CatmullClarkPatch::kType, read_catmull_clark,
                                    write_catmull_clark};

}  // namespace pl
