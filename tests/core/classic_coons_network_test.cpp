// Coons cells on a non-uniform, non-rectangular network: G1 across every
// internal edge, exact reproduction of bicubics on unequal spacing, and the difference from the
// equal-length construction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "classic_test_util.hpp"
#include "core/geometry/differential_geometry.hpp"
#include "core/patch/coons_network_patch.hpp"

namespace pl {
namespace {

using test::max_abs;

// The network's true surface: a graph z = h(x, y), so the distance of a surface point to it is
// measured independently of any parameterisation (|z - h(x, y)|).
struct Graph {
  double h(double a, double b) const {
    return 0.4 * std::sin(2 * a) * std::cos(1.5 * b) + 0.1 * a * b * b;
  }
  double ha(double a, double b) const {
    return 0.8 * std::cos(2 * a) * std::cos(1.5 * b) + 0.1 * b * b;
  }
  double hb(double a, double b) const {
    return -0.6 * std::sin(2 * a) * std::sin(1.5 * b) + 0.2 * a * b;
  }
  double hab(double a, double b) const {
    return -1.2 * std::cos(2 * a) * std::sin(1.5 * b) + 0.2 * b;
  }
};

const std::vector<double> kA = {0, 0.12, 0.3, 0.75, 1.5, 1.8};  // node x, unequally spaced
const std::vector<double> kB = {0, 0.4, 0.55, 1.2, 1.4};        // node y
// Row j's curve parameter is s = x / c[j], column i's is t = y / d[i]: every row and column has
// its own spacing, so opposite cell boundaries have different parametric lengths.
const std::vector<double> kC = {1.0, 0.8, 1.25, 0.9, 1.1};
const std::vector<double> kD = {1.0, 0.85, 1.2, 0.9, 1.1, 1.3};

CoonsNetworkPatch make_network(CoonsNetworkPatch::Lengths lengths) {
  const Graph g;
  const std::size_t ns = kA.size(), nt = kB.size();
  std::vector<std::vector<double>> s(nt, std::vector<double>(ns)), t(ns, std::vector<double>(nt));
  std::vector<Vec3> data;
  for (std::size_t i = 0; i < ns; ++i)
    for (std::size_t j = 0; j < nt; ++j) {
      const double a = kA[i], b = kB[j];
      s[j][i] = a / kC[j];
      t[i][j] = b / kD[i];
      data.push_back({a, b, g.h(a, b)});
      data.push_back(kC[j] * Vec3(1, 0, g.ha(a, b)));           // d/ds of row j
      data.push_back(kD[i] * Vec3(0, 1, g.hb(a, b)));           // d/dt of column i
      data.push_back(kC[j] * kD[i] * Vec3(0, 0, g.hab(a, b)));  // twist
    }
  return CoonsNetworkPatch(ns, nt, s, t, data, lengths);
}

double angle_deg(const SurfaceJet& a, const SurfaceJet& b) {
  const Vec3 na = glm::normalize(glm::cross(a.su, a.sv)),
             nb = glm::normalize(glm::cross(b.su, b.sv));
  return std::atan2(glm::length(glm::cross(na, nb)), glm::dot(na, nb)) * 180 / M_PI;
}

struct Seams {
  double gap = 0, angle = 0;
};
Seams internal_edges(const CoonsNetworkPatch& p) {
  Seams r;
  for (std::size_t ci = 0; ci + 1 < p.ns(); ++ci)
    for (std::size_t cj = 0; cj + 1 < p.nt(); ++cj)
      for (int k = 0; k <= 50; ++k) {
        const double w = k / 50.0;
        if (ci + 2 < p.ns()) {  // edge u = 1 of (ci, cj) with u = 0 of (ci+1, cj)
          const SurfaceJet a = p.cell_jet(ci, cj, {1, w}), b = p.cell_jet(ci + 1, cj, {0, w});
          r.gap = std::max(r.gap, max_abs(a.p - b.p));
          r.angle = std::max(r.angle, angle_deg(a, b));
        }
        if (cj + 2 < p.nt()) {
          const SurfaceJet a = p.cell_jet(ci, cj, {w, 1}), b = p.cell_jet(ci, cj + 1, {w, 0});
          r.gap = std::max(r.gap, max_abs(a.p - b.p));
          r.angle = std::max(r.angle, angle_deg(a, b));
        }
      }
  return r;
}

struct Quality {
  double deviation = 0;        // largest |z - h(x, y)|
  double curvature_range = 0;  // spread of mean curvature: wiggles and flat spots widen it
};
Quality quality(const CoonsNetworkPatch& p) {
  const Graph g;
  Quality q;
  double hmin = 1e300, hmax = -1e300;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) {
      const SurfaceJet s = p.evaluate({i / 200.0, j / 200.0});
      q.deviation = std::max(q.deviation, std::fabs(s.p.z - g.h(s.p.x, s.p.y)));
      const double H = differential_geometry(s).mean;
      hmin = std::min(hmin, H), hmax = std::max(hmax, H);
    }
  q.curvature_range = hmax - hmin;
  return q;
}

TEST(ClassicCoonsNetwork, NonUniformNetworkIsG1AcrossEveryInternalEdge) {
  const CoonsNetworkPatch p = make_network(CoonsNetworkPatch::Lengths::Network);
  const Seams s = internal_edges(p);
  std::printf(
      "figure coons_network_internal_gap %.3e\nfigure coons_network_max_normal_angle_deg %.3e\n",
      s.gap, s.angle);
  EXPECT_LT(s.gap, 1e-13);
  EXPECT_LT(s.angle, 1e-6);
  double fd = 0;
  for (const Vec2& x : test::random_domain_points(200, 12))
    fd = std::max(fd, test::fd_mismatch(p, x, 1e-6));
  std::printf("figure coons_network_fd %.3e\n", fd);
  EXPECT_LT(fd, 1e-5);
  EXPECT_LT(test::interface_mismatch(p, test::random_domain_points(20, 13)), 1e-11);
}

TEST(ClassicCoonsNetwork, CellsReproduceTheirBoundaryAndCrossBoundaryData) {
  const CoonsNetworkPatch p = make_network(CoonsNetworkPatch::Lengths::Network);
  double worst = 0;
  for (std::size_t ci = 0; ci + 1 < p.ns(); ++ci)
    for (std::size_t cj = 0; cj + 1 < p.nt(); ++cj) {
      const CellLengths L = p.cell_lengths(ci, cj);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          const Vec3* d = &p.control_points()[((ci + a) * p.nt() + cj + b) * 4];
          const SurfaceJet s = p.cell_jet(ci, cj, {double(a), double(b)});
          const double S = b ? L.S1 : L.S0, T = a ? L.T1 : L.T0;
          const Vec3 twist = S * T * d[3] + (L.S1 - L.S0) * d[1] + (L.T1 - L.T0) * d[2];
          worst = std::max({worst, max_abs(s.p - d[0]), max_abs(s.su - S * d[1]),
                            max_abs(s.sv - T * d[2]), max_abs(s.suv - twist)});
        }
    }
  std::printf("figure coons_network_corner_data_error %.3e\n", worst);
  EXPECT_LT(worst, 1e-13);
}

TEST(ClassicCoonsNetwork, BicubicOnUnequalRectangularSpacingIsReproducedExactly) {
  // h is bicubic in (x, y); with s = x and t = y the Hermite data are exact, so the network-length
  // construction must reproduce h, and the equal-length one cannot.
  const auto h = [](double x, double y) {
    return 0.3 * x * x * y - 0.2 * y * y * y + 0.5 * x * x * x * y * y;
  };
  const auto hx = [](double x, double y) { return 0.6 * x * y + 1.5 * x * x * y * y; };
  const auto hy = [](double x, double y) { return 0.3 * x * x - 0.6 * y * y + x * x * x * y; };
  const auto hxy = [](double x, double y) { return 0.6 * x + 3 * x * x * y; };
  const std::size_t ns = kA.size(), nt = kB.size();
  std::vector<std::vector<double>> s(nt, kA), t(ns, kB);
  std::vector<Vec3> data;
  for (double a : kA)
    for (double b : kB) {
      data.push_back({a, b, h(a, b)});
      data.push_back({1, 0, hx(a, b)});
      data.push_back({0, 1, hy(a, b)});
      data.push_back({0, 0, hxy(a, b)});
    }
  double err[2] = {0, 0};
  for (int m = 0; m < 2; ++m) {
    const CoonsNetworkPatch p(
        ns, nt, s, t, data,
        m == 0 ? CoonsNetworkPatch::Lengths::Network : CoonsNetworkPatch::Lengths::Equal);
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; j <= 100; ++j) {
        const Vec3 q = p.evaluate({i / 100.0, j / 100.0}).p;
        err[m] = std::max(err[m], std::fabs(q.z - h(q.x, q.y)));
      }
  }
  std::printf(
      "figure coons_bicubic_error_network_lengths %.3e\nfigure coons_bicubic_error_equal_lengths "
      "%.3e\n",
      err[0], err[1]);
  EXPECT_LT(err[0], 1e-12);
  EXPECT_GT(err[1], 1e-3);
}

TEST(ClassicCoonsNetwork, EqualLengthConstructionDeviatesOnUnequalSpacing) {
  const Quality net = quality(make_network(CoonsNetworkPatch::Lengths::Network));
  const Quality eq = quality(make_network(CoonsNetworkPatch::Lengths::Equal));
  const Seams eq_seams = internal_edges(make_network(CoonsNetworkPatch::Lengths::Equal));
  std::printf(
      "figure coons_network_deviation_network_lengths %.3e\n"
      "figure coons_network_deviation_equal_lengths %.3e\n"
      "figure coons_network_H_range_network_lengths %.3e\n"
      "figure coons_network_H_range_equal_lengths %.3e\n"
      "figure coons_network_equal_lengths_normal_angle_deg %.3e\n",
      net.deviation, eq.deviation, net.curvature_range, eq.curvature_range, eq_seams.angle);
  // Same node data, same tangent planes at the nodes: only the parametric lengths differ.
  EXPECT_LT(net.deviation, 0.02);
  EXPECT_GT(eq.deviation, 5 * net.deviation);
  EXPECT_GT(eq.curvature_range, 2 * net.curvature_range);
}

TEST(ClassicCoonsNetwork, InvalidNetworkIsRejected) {
  const auto data = test::random_points(16, 1);
  EXPECT_THROW(
      CoonsNetworkPatch(2, 2, {{0, 1}, {0, 1}}, {{0, 1}, {0, 1}}, test::random_points(15, 1)),
      std::invalid_argument);
  EXPECT_THROW(CoonsNetworkPatch(2, 2, {{0, 1}, {1, 1}}, {{0, 1}, {0, 1}}, data),
               std::invalid_argument);
  EXPECT_THROW(CoonsNetworkPatch(2, 2, {{0, 1}}, {{0, 1}, {0, 1}}, data), std::invalid_argument);
}

}  // namespace
}  // namespace pl
