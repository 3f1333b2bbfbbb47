// {"type": "hermite", "q": [16 vectors]}: the matrix Q of hermite_patch.hpp, row by row.
#include "core/io/patch_codec.hpp"
#include "core/patch/hermite_patch.hpp"

namespace pl {

namespace {
constexpr char kKey[] = "q";
}

constinit const PatchCodec kHermitePatchCodec = point_list_codec<HermitePatch, kKey, 16>();

}  // namespace pl
