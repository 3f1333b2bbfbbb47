#include "core/network/gb_face_interior.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/patch/gb/default_net.hpp"

namespace pl {

namespace {

// Rows 0 and 1 of one side elevated to degree d, row 1 for cross-boundary degree d (the .gbp
// net's B^d_k(h)): row0 + (3/d) (inner - row0), the cubic's cross derivative 3 (inner - boundary).
std::array<std::vector<Vec3>, 2> g1_rows(const CubicRibbon& r, int d) {
  std::vector<Vec3> b = BezierCurve(std::vector<Vec3>(r.boundary.begin(), r.boundary.end()))
                            .elevated_to(d)
                            .control_points();
  std::vector<Vec3> in = BezierCurve(std::vector<Vec3>(r.inner.begin(), r.inner.end()))
                             .elevated_to(d)
                             .control_points();
  for (int j = 0; j <= d; ++j) in[j] = b[j] + (3.0 / d) * (in[j] - b[j]);
  return {std::move(b), std::move(in)};
}

// gb_face_default_net of ribbons already as filled.
std::vector<Vec3> default_net_as_filled(const FaceRibbons& ribbons, int d) {
  const int n = static_cast<int>(ribbons.sides.size());
  std::vector<std::array<std::vector<Vec3>, 2>> rows;
  for (const CubicRibbon& r : ribbons.sides) rows.push_back(g1_rows(r, d));
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
  for (std::size_t k = 0; k < net.size(); ++k) placed[k] = k > 0 && gb_ring(n, d, k) < 2;
  return gb_default_points(n, d, std::move(net), std::span<const bool>(placed.get(), net.size()));
}

void check_degree(int d) {
  if (d < 3 || d > kMaxGBFaceDegree)
    throw std::invalid_argument("a GB face's degree is 3 .. " + std::to_string(kMaxGBFaceDegree) +
                                ", got " + std::to_string(d));
}

}  // namespace

std::unique_ptr<GBInteriorPatch> gb_face_interior_patch(const FaceRibbons& input, int degree,
                                                        std::span<const InteriorOffset> offsets,
                                                        GBDomainKind* used) {
  std::unique_ptr<GBRibbonPatch> filling = gb_face_patch(input, used);
  return gb_interior_face_patch(ribbons_as_filled(input), std::move(*filling), degree, offsets);
}

std::unique_ptr<Patch> gb_face_patch(const FaceRibbons& input, int degree,
                                     std::span<const InteriorOffset> offsets, GBDomainKind* used) {
  if (!gb_face_interior_form(degree, offsets)) return gb_face_patch(input, used);
  return gb_face_interior_patch(input, degree, offsets, used);
}

std::vector<Vec3> gb_face_default_net(const FaceRibbons& ribbons, int d) {
  check_degree(d);
  return default_net_as_filled(ribbons_as_filled(ribbons), d);
}

std::size_t interior_point_index(int n, int d, const InteriorOffset& at) {
  return at.centre ? 0 : gb_net_index(n, d, at.side, at.j, at.layer);
}

InteriorOffset interior_point_name(int n, int d, std::size_t index) {
  if (index == 0) return {.centre = true};
  for (int k = 0; k < GBPatch::layers(d); ++k)
    for (int i = 0; i < n; ++i)
      for (int j = k; j <= d - 1 - k; ++j)
        if (gb_net_index(n, d, i, j, k) == index) return {.side = i, .j = j, .layer = k};
  throw std::invalid_argument("net index " + std::to_string(index) + " beyond the degree-" +
                              std::to_string(d) + " net of " + std::to_string(n) + " sides");
}

std::unique_ptr<GBInteriorPatch> gb_interior_face_patch(const FaceRibbons& r, GBRibbonPatch filling,
                                                        int d,
                                                        std::span<const InteriorOffset> offsets) {
  check_degree(d);
  const int n = static_cast<int>(r.sides.size());
  for (const InteriorOffset& o : offsets)
    if (const std::string why = interior_offset_problem(n, d, o); !why.empty())
      throw std::invalid_argument(why);
  const std::vector<Vec3> defaults = default_net_as_filled(r, d);
  std::vector<Vec3> net = defaults;
  for (const InteriorOffset& o : offsets) net[interior_point_index(n, d, o)] += o.by;
  return std::make_unique<GBInteriorPatch>(std::move(filling), d, defaults, net);
}

std::vector<InteriorOffset> gb_face_offsets_for_degree(const FaceRibbons& ribbons, int old_degree,
                                                       std::span<const InteriorOffset> offsets,
                                                       int new_degree) {
  check_degree(old_degree);
  check_degree(new_degree);
  if (offsets.empty()) return {};
  const auto from = gb_face_interior_patch(ribbons, old_degree, offsets);
  const auto to = gb_face_interior_patch(ribbons, new_degree, {});
  const int n = from->sides();
  const std::vector<std::size_t>& free = to->free_points();
  if (free.empty()) return {};
  // A sample of the domain with several times more points than unknowns.
  std::vector<Vec2> xs;
  for (int density = 16; density <= 256; density *= 2) {
    xs = to->domain().tessellate(density).points;
    if (xs.size() >= 6 * free.size()) break;
  }
  const Eigen::Index rows = static_cast<Eigen::Index>(xs.size());
  // The displacement field of the old degree, sum offset_p phi^old_p, and the new degree's free
  // blends at the samples: one basis evaluation per sample and patch fills a whole row.
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(rows, 3);
  Eigen::MatrixXd a(rows, static_cast<Eigen::Index>(free.size()));
  std::vector<std::size_t> at;
  for (const InteriorOffset& o : offsets) at.push_back(interior_point_index(n, old_degree, o));
  std::vector<Jet> phi_old(from->size()), phi_new(to->size());
  for (Eigen::Index s = 0; s < rows; ++s) {
    from->basis(xs[s], phi_old);
    for (std::size_t p = 0; p < offsets.size(); ++p)
      for (int c = 0; c < 3; ++c) b(s, c) += phi_old[at[p]].f * offsets[p].by[c];
    to->basis(xs[s], phi_new);
    for (std::size_t p = 0; p < free.size(); ++p) a(s, Eigen::Index(p)) = phi_new[free[p]].f;
  }
  const Eigen::MatrixXd x = a.colPivHouseholderQr().solve(b);
  double largest = 0;
  for (Eigen::Index p = 0; p < x.rows(); ++p) largest = std::max(largest, x.row(p).norm());
  std::vector<InteriorOffset> out;
  for (std::size_t p = 0; p < free.size(); ++p) {
    const Eigen::Index r = Eigen::Index(p);
    if (!(x.row(r).norm() > 1e-14 * largest)) continue;
    InteriorOffset o = interior_point_name(n, new_degree, free[p]);
    o.by = Vec3(x(r, 0), x(r, 1), x(r, 2));
    out.push_back(o);
  }
  return out;
}

}  // namespace pl
