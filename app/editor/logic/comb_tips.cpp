#include "app/editor/logic/comb_tips.hpp"

#include <algorithm>
#include <cmath>

#include "render/default_view.hpp"

namespace pl {

std::vector<Vec3> comb_tips(std::span<const ViewCombs> views, const DisplaySettings& settings) {
  std::vector<Vec3> tips;
  if (!settings.combs) return tips;
  std::vector<double> own;
  double common = 0;  // the smallest positive automatic scale: the panes share it
  for (const ViewCombs& v : views) {
    own.push_back(automatic_comb_scale_of(v.combs, v.diagonal));
    if (own.back() > 0) common = common > 0 ? std::min(common, own.back()) : own.back();
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    const double automatic = views.size() > 1 && common > 0 ? common : own[i];
    const double scale = settings.comb_length.value_or(automatic) * settings.comb_scale;
    const double cap = kCombCap * kDefaultCombFraction * views[i].diagonal * settings.comb_scale;
    if (scale > 0) append_tooth_tips(views[i].combs, scale, cap, tips);
  }
  return tips;
}

}  // namespace pl
