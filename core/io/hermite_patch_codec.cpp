// {"type": "hermite", "q": [16 vectors]}: the matrix Q of hermite_patch.hpp, row by row.
#include "core/io/patch_codec.hpp"
#include "core/patch/hermite_patch.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_hermite_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "q"});
  const JsonNode q = node.at("q");
  q.items(16);
  return std::make_unique<HermitePatch>(q.points());
}

void write_hermite_patch(const Patch& patch, nlohmann::json& out) {
  out["q"] = points_json(patch.control_points());
}

}  // namespace

const PatchCodec kHermitePatchCodec{HermitePatch::kType, read_hermite_patch, write_hermite_patch};

}  // namespace pl
