#include <array>

#include "core/io/bezier_patch_codec.hpp"
#include "core/io/bspline_patch_codec.hpp"
#include "core/io/catmull_clark_codec.hpp"
#include "core/io/coons_network_codec.hpp"
#include "core/io/gap_fill_codec.hpp"
#include "core/io/gb_patch_codec.hpp"
#include "core/io/gb_ribbon_patch_codec.hpp"
#include "core/io/gregory_patch_codecs.hpp"
#include "core/io/hermite_patch_codec.hpp"
#include "core/io/interpolating_patch_codec.hpp"
#include "core/io/nurbs_patch_codec.hpp"
#include "core/io/pair_join_codec.hpp"
#include "core/io/patch_codec.hpp"

namespace pl {

std::span<const PatchCodec> patch_codecs() {
  static const std::array codecs{
      PatchCodec{"bezier", read_bezier_patch, write_bezier_patch},
      PatchCodec{"gb", read_gb_patch, write_gb_patch},
      PatchCodec{"gb-ribbons", read_gb_ribbon_patch, write_gb_ribbon_patch},
      PatchCodec{"gregory-quad", read_gregory_quad_patch, write_gregory_quad_patch},
      PatchCodec{"gregory-tri", read_gregory_tri_patch, write_gregory_tri_patch},
      PatchCodec{"interpolating", read_interpolating_patch, write_interpolating_patch},
      PatchCodec{"hermite", read_hermite_patch, write_hermite_patch},
      PatchCodec{"bspline", read_bspline_patch, write_bspline_patch},
      PatchCodec{"nurbs", read_nurbs_patch, write_nurbs_patch},
      PatchCodec{"coons-network", read_coons_network, write_coons_network},
      PatchCodec{"pair-join", read_pair_join, write_pair_join},
      PatchCodec{"gap-fill", read_gap_fill, write_gap_fill},
      PatchCodec{"catmull-clark", read_catmull_clark, write_catmull_clark},
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

}  // namespace pl
