// {"type": "gregory-quad", "points": [20 points]} and {"type": "gregory-tri", "points": [18
// points]}; point order in docs/patch-types.md and the patch headers.
#include "core/io/patch_codec.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"

namespace pl {

namespace {
constexpr char kKey[] = "points";
}

// Both types are their fixed number of points (kPointCount) in the order of their header.
constinit const PatchCodec kGregoryQuadCodec =
    point_list_codec<GregoryQuadPatch, kKey, GregoryQuadPatch::kPointCount>();
constinit const PatchCodec kGregoryTriCodec =
    point_list_codec<GregoryTriPatch, kKey, GregoryTriPatch::kPointCount>();

}  // namespace pl
