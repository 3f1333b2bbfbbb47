#include "core/network/gb_face_interior.hpp"

#include <algorithm>
#include <memory>

#include "core/domain/concave_polygon.hpp"
#include "core/patch/gb/default_net.hpp"
#include "core/patch/gb/gb_centred_ribbon_patch.hpp"
#include "core/patch/gb/ribbon_elevation.hpp"

namespace pl {

namespace {

// Rows 0 and 1 of one side elevated to degree d, row 1 for cross-boundary degree m:
// row0 + (3/m) (inner - row0), the same cross derivative 3 (inner - boundary) as the cubic.
std::array<std::vector<Vec3>, 2> g1_rows(const CubicRibbon& r, int d, int m) {
  std::vector<Vec3> b = BezierCurve(std::vector<Vec3>(r.boundary.begin(), r.boundary.end()))
                            .elevated_to(d)
                            .control_points();
  std::vector<Vec3> in = BezierCurve(std::vector<Vec3>(r.inner.begin(), r.inner.end()))
                             .elevated_to(d)
                             .control_points();
  if (m != 3)
    for (int j = 0; j <= d; ++j) in[j] = b[j] + (3.0 / m) * (in[j] - b[j]);
  return {std::move(b), std::move(in)};
}

}  // namespace

std::vector<Vec3> gb_face_default_net(const FaceRibbons& ribbons, int d) {
  const int n = static_cast<int>(ribbons.sides.size());
  std::vector<std::array<std::vector<Vec3>, 2>> rows;
  for (const CubicRibbon& r : ribbons.sides) rows.push_back(g1_rows(r, d, d));
  std::vector<Vec3> net(GBPatch::point_count(n, d));
  const auto placed = std::make_unique<bool[]>(net.size());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) net[gb_net_index(n, d, i, j, 0)] = rows[i][0][j];
    for (int j = 1; j <= d - 2; ++j) {
      Vec3 p = rows[i][1][j];
      // The twist at vertex i-1 is stored once: the mean of the two ribbons' twists.
      if (j == 1) p = 0.5 * (p + rows[(i + n - 1) % n][1][d - 1]);
      net[gb_net_index(n, d, i, j, 1)] = p;
    }
  }
  for (std::size_t k = 1; k < net.size(); ++k) placed[k] = gb_ring(n, d, k) < 2;
  return gb_default_points(n, d, std::move(net), std::span<const bool>(placed.get(), net.size()));
}

std::unique_ptr<Patch> gb_interior_face_patch(const FaceRibbons& r, std::vector<Vec2> vertices,
                                              int d, std::span<const InteriorOffset> offsets) {
  const int n = static_cast<int>(r.sides.size());
  for (const InteriorOffset& o : offsets)
    if (const std::string why = interior_offset_problem(n, d, o); !why.empty())
      throw std::invalid_argument(why);
  ConcavePolygonDomain domain(std::move(vertices));
  const int l = std::max(2, gb_face_layers(d)), m = 2 * l - 1;
  const std::vector<Vec3> defaults = gb_face_default_net(r, d);
  std::vector<Vec3> net = defaults;
  bool centre_moved = false;
  for (const InteriorOffset& o : offsets) {
    if (o.centre) centre_moved = true;
    net[o.centre ? 0 : gb_net_index(n, d, o.side, o.j, o.layer)] += o.by;
  }
  std::vector<std::vector<std::vector<Vec3>>> ribbons(n);
  for (int i = 0; i < n; ++i) {
    auto [row0, row1] = g1_rows(r.sides[i], d, m);
    ribbons[i] = {std::move(row0), std::move(row1)};
    for (int k = 2; k < l; ++k) {
      std::vector<Vec3>& row = ribbons[i].emplace_back(d + 1);
      for (int j = 0; j <= d; ++j) row[j] = net[gb_net_index(n, d, i, j, k)];
    }
  }
  // Sides behind a reflex corner get layers until l_i >= d_i, where the blend has no pole
  // (gb_face.cpp); each added layer keeps the ribbon's rows 0 and 1 data exactly.
  for (int i : GBRibbonPatch::sides_without_positive_pair(domain))
    while (static_cast<int>(ribbons[i].size()) < d) ribbons[i] = ribbon_with_layer(ribbons[i]);
  GBRibbonPatch patch(std::move(domain), ribbons);
  try {
    return std::make_unique<GBCentredRibbonPatch>(patch, net[0], defaults[0]);
  } catch (const std::invalid_argument&) {
    // A face too concave for the central point's weight has no central point; only an offset
    // that needs one is an error.
    if (centre_moved) throw;
    return std::make_unique<GBRibbonPatch>(std::move(patch));
  }
}

}  // namespace pl
