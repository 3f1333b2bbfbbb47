#include "core/cad/side_matching.hpp"

#include <algorithm>
#include <numeric>

namespace pl {

namespace {

bool same(const SideSamples& a, const SideSamples& b, bool reversed, double eps) {
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k)
    if (glm::length(a[k] - b[reversed ? n - 1 - k : k]) > eps) return false;
  return true;
}

}  // namespace

std::vector<SideGroup> match_sides(const std::vector<SideSamples>& sides,
                                   const std::vector<SideRef>& refs, double eps) {
  const int n = static_cast<int>(sides.size());
  const std::size_t mid = kSideParams.size() / 2;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return sides[a][mid].x < sides[b][mid].x; });
  // Each side links to the first earlier side (in sorted order) it matches: a forest whose
  // roots matched nothing before them. A group is a tree; directions compose along the links.
  std::vector<int> link(n, -1);
  std::vector<bool> flip(n, false);
  for (int a = 0; a < n; ++a) {
    const int i = order[a];
    for (int b = a + 1; b < n && sides[order[b]][mid].x - sides[i][mid].x <= eps; ++b) {
      const int j = order[b];
      if (link[j] >= 0 || glm::length(sides[i][mid] - sides[j][mid]) > eps) continue;
      for (bool rev : {false, true})
        if (same(sides[i], sides[j], rev, eps)) {
          link[j] = i, flip[j] = rev;
          break;
        }
    }
  }
  std::vector<int> group_of(n, -1);
  std::vector<SideGroup> groups;
  for (int a = 0; a < n; ++a) {  // sorted order: a root comes before everything linked to it
    const int i = order[a];
    bool rev = false;
    int r = i;
    while (link[r] >= 0) rev = rev != flip[r], r = link[r];
    if (group_of[r] < 0) {
      group_of[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group_of[r]].members.push_back(refs[i]);
    groups[group_of[r]].reversed.push_back(rev);
  }
  return groups;
}

}  // namespace pl
