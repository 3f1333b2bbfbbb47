// The one table of patch codecs (patch_codec.hpp).
#include <array>

#include "core/io/patch_codec.hpp"

namespace pl {

std::span<const PatchCodec> patch_codecs() {
  static const std::array codecs{
      kBezierPatchCodec,  kGBPatchCodec,      kGBRibbonPatchCodec,
      kGregoryQuadCodec,  kGregoryTriCodec,   kInterpolatingPatchCodec,
      kHermitePatchCodec, kBSplinePatchCodec, kNurbsPatchCodec,
      kCoonsNetworkCodec, kPairJoinCodec,     kGapFillCodec,
      kCatmullClarkCodec, kRibbonPatchCodec,
  };
  return codecs;
}

const PatchCodec* find_patch_codec(const std::string& type) {
  for (const PatchCodec& c : patch_codecs())
    if (type == c.type) return &c;
  return nullptr;
}

nlohmann::json point_json(const Vec3& p) {
  return nlohmann::json::array({p.x, p.y, p.z});
}

nlohmann::json points_json(const std::vector<Vec3>& points) {
  nlohmann::json a = nlohmann::json::array();
  for (const Vec3& p : points) a.push_back(point_json(p));
  return a;
}

std::vector<Vec3> read_point_list(const JsonNode& node, const char* key, std::size_t count) {
  node.allow_only({"type", "name", key});
  const JsonNode points = node.at(key);
  points.items(count);
  return points.points();
}

}  // namespace pl
