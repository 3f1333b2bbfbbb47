// {"type": "hermite", "q": [16 vectors]}: the matrix Q of hermite_patch.hpp, row by row.
#include "core/io/hermite_patch_codec.hpp"

#include "core/patch/hermite_patch.hpp"

namespace pl {

std::unique_ptr<Patch> read_hermite_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "q"});
  const JsonNode q = node.at("q");
  q.items(16);
  return std::make_unique<HermitePatch>(q.points());
}

void write_hermite_patch(const Patch& patch, nlohmann::json& out) {
  out["q"] = points_json(patch.control_points());
}

}  // namespace pl
