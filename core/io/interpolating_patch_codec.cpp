// {"type": "interpolating", "points": [16 points]}: points[i*4+j] is hit at (u,v) = (i/3, j/3).
#include "core/io/patch_codec.hpp"
#include "core/patch/interpolating_patch.hpp"

namespace pl {

namespace {
constexpr char kKey[] = "points";
}

constinit const PatchCodec kInterpolatingPatchCodec =
    point_list_codec<InterpolatingPatch, kKey, 16>();

}  // namespace pl
