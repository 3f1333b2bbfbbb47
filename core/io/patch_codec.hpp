// Reading and writing explicit patches of the scene format, one codec per "type": each is defined
// in its own file (core/io/NAME_codec.cpp) with the type name its patch class carries (kType),
// declared below, and registered in the one table of patch_codecs.cpp. A new patch type adds a
// codec file, its line below and its line in the table.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "core/io/json_node.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

struct PatchCodec {
  const char* type;
  // Reads the patch object (its "type" and "name" keys are already known to be valid).
  std::unique_ptr<Patch> (*read)(const JsonNode& node);
  // Writes every key except "type" and "name".
  void (*write)(const Patch& patch, nlohmann::json& out);
};

// The codecs, in the order of the table.
extern const PatchCodec kBezierPatchCodec, kGBPatchCodec, kGBRibbonPatchCodec, kGregoryQuadCodec,
    kGregoryTriCodec, kInterpolatingPatchCodec, kHermitePatchCodec, kBSplinePatchCodec,
    kNurbsPatchCodec, kCoonsNetworkCodec, kPairJoinCodec, kGapFillCodec, kCatmullClarkCodec,
    kRibbonPatchCodec;

std::span<const PatchCodec> patch_codecs();
const PatchCodec* find_patch_codec(const std::string& type);

// Helpers shared by codecs.
nlohmann::json point_json(const Vec3& p);
nlohmann::json points_json(const std::vector<Vec3>& points);
// The `count` points under `key` of a patch stored as one list of points (Hermite, interpolating,
// Gregory): no other key than "type", "name" and `key` is allowed.
std::vector<Vec3> read_point_list(const JsonNode& node, const char* key, std::size_t count);

// The codec of a type P stored as its Count control points, in their order, under Key (a
// constexpr char array of the codec's file): P is constructed from the points alone.
template <class P, const char* Key, std::size_t Count>
constexpr PatchCodec point_list_codec() {
  return {P::kType,
          [](const JsonNode& node) -> std::unique_ptr<Patch> {
            return std::make_unique<P>(read_point_list(node, Key, Count));
          },
          [](const Patch& patch, nlohmann::json& out) {
            out[Key] = points_json(patch_ref<P>(patch).control_points());
          }};
}

}  // namespace pl
