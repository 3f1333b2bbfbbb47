#include "core/patch/gb/default_net.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace pl {

namespace {

// Ribbon i's grid over the working copy of the points.
struct Net {
  int n, d;
  std::vector<Vec3>& p;
  Vec3& at(int i, int j, int k) { return p[gb_net_index(n, d, i, j, k)]; }
  // Linear extrapolation of ribbon i's rows 0 and 1 to row k.
  Vec3 extrapolated(int i, int j, int k) {
    return at(i, j, 0) + double(k) * (at(i, j, 1) - at(i, j, 0));
  }
};

}  // namespace

int gb_ring(int n, int d, std::size_t k) {
  if (k == 0) return -1;
  std::size_t first = 1;
  for (int r = 0; r < GBPatch::layers(d); ++r) {
    const std::size_t count = static_cast<std::size_t>(n) * (d - 2 * r);
    if (k < first + count) return r;
    first += count;
  }
  throw std::invalid_argument("gb_ring: index " + std::to_string(k) + " beyond the net");
}

std::vector<Vec3> gb_default_points(int n, int d, std::vector<Vec3> p,
                                    std::span<const bool> placed) {
  if (n < 3 || d < 1) throw std::invalid_argument("gb_default_net: a net needs n >= 3, d >= 1");
  const int l = GBPatch::layers(d);
  const std::size_t size = GBPatch::point_count(n, d);
  if (placed.size() != size || p.size() != size)
    throw std::invalid_argument("gb_default_net: " + std::to_string(placed.size()) + " flags for " +
                                std::to_string(size) + " points");
  for (std::size_t k = 1; k < size; ++k)
    if (gb_ring(n, d, k) == 0 && !placed[k])
      throw std::invalid_argument("gb_default_net: boundary point " + std::to_string(k) +
                                  " must be placed");
  Net net{n, d, p};
  const auto unplaced = [&](int i, int j, int k) { return !placed[gb_net_index(n, d, i, j, k)]; };

  // 1. Ring 1: parallelogram twists, then the cross vectors between them.
  if (l >= 2) {
    for (int i = 0; i < n; ++i)
      if (unplaced(i, 1, 1)) net.at(i, 1, 1) = net.at(i, 1, 0) + net.at(i, 0, 1) - net.at(i, 0, 0);
    for (int i = 0; i < n; ++i)
      for (int j = 2; j <= d - 2; ++j)
        if (unplaced(i, j, 1)) {
          const double t = double(j - 1) / (d - 2);
          net.at(i, j, 1) = net.at(i, j, 0) + (1 - t) * (net.at(i, 1, 1) - net.at(i, 1, 0)) +
                            t * (net.at(i, d - 1, 1) - net.at(i, d - 1, 0));
        }
  }
  // 2. Corner blocks, rings >= 2: every block is ribbon i's j < l block for exactly one i.
  for (int i = 0; i < n; ++i)
    for (int j = 2; j < l; ++j)
      for (int k = 2; k < l; ++k) {
        if (!unplaced(i, j, k)) continue;
        const Vec3 q00 = net.at(i, 0, 0), q10 = net.at(i, 1, 0), q01 = net.at(i, 0, 1),
                   q11 = net.at(i, 1, 1);
        const Vec3 bilinear = q00 + double(j) * (q10 - q00) + double(k) * (q01 - q00) +
                              double(j) * k * (q11 - q10 - q01 + q00);
        const Vec3 across = net.at(i, 0, k) + double(j) * (net.at(i, 1, k) - net.at(i, 0, k));
        net.at(i, j, k) = net.extrapolated(i, j, k) + across - bilinear;
      }
  // 3. Middle column of even degrees, rings >= 2 (its row neighbours are corner-block points).
  if (d % 2 == 0) {
    const int m = d / 2;
    for (int i = 0; i < n; ++i)
      for (int k = 2; k < l; ++k)
        if (unplaced(i, m, k))
          net.at(i, m, k) = net.extrapolated(i, m, k) +
                            0.5 * (net.at(i, m - 1, k) + net.at(i, m + 1, k)) -
                            0.5 * (net.extrapolated(i, m - 1, k) + net.extrapolated(i, m + 1, k));
  }
  // 4. The central point.
  if (!placed[0]) {
    Vec3 c(0);
    if (d % 2 == 1) {
      const int m = d / 2;
      for (int i = 0; i < n; ++i) c += net.at(i, m, m);
      c /= double(n);
    } else {
      const int m = d / 2;
      for (int i = 0; i < n; ++i) c += 2.0 * net.at(i, m, m - 1) - net.at(i, m - 1, m - 1);
      c /= double(n);
    }
    p[0] = c;
  }
  return p;
}

GBPatch gb_default_net(const GBPatch& patch, std::span<const bool> placed) {
  return GBPatch(patch.sides(), patch.degree(),
                 gb_default_points(patch.sides(), patch.degree(), patch.control_points(), placed));
}

GBPatch gb_default_net(const GBPatch& patch, int kept_rings) {
  if (kept_rings < 1) throw std::invalid_argument("gb_default_net: the boundary must be kept");
  // std::vector<bool> is not contiguous, so the flags live in a plain array.
  const auto placed = std::make_unique<bool[]>(patch.size());
  for (std::size_t k = 1; k < patch.size(); ++k)
    placed[k] = gb_ring(patch.sides(), patch.degree(), k) < kept_rings;
  return gb_default_net(patch, std::span<const bool>(placed.get(), patch.size()));
}

}  // namespace pl
