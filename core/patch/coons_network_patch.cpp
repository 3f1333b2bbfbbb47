#include "core/patch/coons_network_patch.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "core/curve/hermite_curve.hpp"

namespace pl {

CoonsNetworkPatch::CoonsNetworkPatch(std::size_t ns, std::size_t nt,
                                     std::vector<std::vector<double>> s,
                                     std::vector<std::vector<double>> t, std::vector<Vec3> data,
                                     Lengths lengths)
    : UnitSquarePatch(std::move(data)),
      ns_(ns),
      nt_(nt),
      s_(std::move(s)),
      t_(std::move(t)),
      lengths_(lengths) {
  if (ns_ < 2 || nt_ < 2) throw std::invalid_argument("a Coons network needs at least 2 x 2 nodes");
  if (points_.size() != 4 * ns_ * nt_)
    throw std::invalid_argument("a " + std::to_string(ns_) + " x " + std::to_string(nt_) +
                                " Coons network needs " + std::to_string(4 * ns_ * nt_) +
                                " vectors (r, r_s, r_t, r_st per node), got " +
                                std::to_string(points_.size()));
  const auto check = [](const std::vector<std::vector<double>>& lines, std::size_t count,
                        std::size_t len, const char* what) {
    if (lines.size() != count)
      throw std::invalid_argument(std::string(what) + " needs " + std::to_string(count) +
                                  " lines, got " + std::to_string(lines.size()));
    for (std::size_t l = 0; l < count; ++l) {
      if (lines[l].size() != len)
        throw std::invalid_argument(std::string(what) + "[" + std::to_string(l) + "] needs " +
                                    std::to_string(len) + " values");
      for (std::size_t k = 0; k < len; ++k)
        if (!std::isfinite(lines[l][k]) || (k > 0 && !(lines[l][k] > lines[l][k - 1])))
          throw std::invalid_argument(std::string(what) + "[" + std::to_string(l) +
                                      "]: parameters must be finite and strictly increasing");
    }
  };
  check(s_, nt_, ns_, "s");
  check(t_, ns_, nt_, "t");
  double ss = 0, tt = 0;
  for (const auto& row : s_) ss += (row.back() - row.front()) / double(ns_ - 1);
  for (const auto& col : t_) tt += (col.back() - col.front()) / double(nt_ - 1);
  mean_s_ = ss / double(nt_);
  mean_t_ = tt / double(ns_);
}

CellLengths CoonsNetworkPatch::cell_lengths(std::size_t ci, std::size_t cj) const {
  if (lengths_ == Lengths::Equal) return {mean_s_, mean_s_, mean_t_, mean_t_};
  return {s_[cj][ci + 1] - s_[cj][ci], s_[cj + 1][ci + 1] - s_[cj + 1][ci],
          t_[ci][cj + 1] - t_[ci][cj], t_[ci + 1][cj + 1] - t_[ci + 1][cj]};
}

ControlPointKind CoonsNetworkPatch::kind(std::size_t k) const {
  if (k % 4 != 0) return ControlPointKind::Inner;  // derivative vectors
  const std::size_t node = k / 4, i = node / nt_, j = node % nt_;
  return (i == 0 || j == 0 || i + 1 == ns_ || j + 1 == nt_) ? ControlPointKind::Boundary
                                                            : ControlPointKind::Inner;
}

CoonsNetworkPatch::Cell CoonsNetworkPatch::locate(Vec2 x) const {
  const double fu = x.x * double(ns_ - 1), fv = x.y * double(nt_ - 1);
  // Points outside [0,1]^2 (finite differences at the border) extend the border cells.
  const std::size_t ci = static_cast<std::size_t>(std::clamp(std::floor(fu), 0.0, double(ns_ - 2)));
  const std::size_t cj = static_cast<std::size_t>(std::clamp(std::floor(fv), 0.0, double(nt_ - 2)));
  return {ci, cj, {fu - double(ci), fv - double(cj)}};
}

std::size_t CoonsNetworkPatch::data_index(std::size_t ci, std::size_t cj, int local) const {
  const std::size_t i = ci + local / 8, j = cj + (local / 4) % 2;
  return (i * nt_ + j) * 4 + local % 4;
}

namespace {
// Local-cell jets to domain jets: u = x (ns-1) - ci, so d/dx = (ns-1) d/du.
Jet to_domain(const Jet& w, double a, double b) {
  return Jet(w.f, a * w.fu, b * w.fv, a * a * w.fuu, a * b * w.fuv, b * b * w.fvv);
}
}  // namespace

void CoonsNetworkPatch::basis(Vec2 x, std::span<Jet> out) const {
  assert(out.size() == size());
  std::fill(out.begin(), out.end(), Jet(0.0));
  const Cell c = locate(x);
  std::array<Jet, 16> local;
  coons_cell_basis(c.uv, cell_lengths(c.ci, c.cj), local);
  for (int l = 0; l < 16; ++l)
    out[data_index(c.ci, c.cj, l)] = to_domain(local[l], double(ns_ - 1), double(nt_ - 1));
}

SurfaceJet CoonsNetworkPatch::cell_jet(std::size_t ci, std::size_t cj, Vec2 uv) const {
  std::array<Jet, 16> local;
  coons_cell_basis(uv, cell_lengths(ci, cj), local);
  SurfaceJet s;
  for (int l = 0; l < 16; ++l) add_scaled(s, local[l], points_[data_index(ci, cj, l)]);
  return s;
}

SurfaceJet CoonsNetworkPatch::evaluate(Vec2 x) const {
  const Cell c = locate(x);
  SurfaceJet s = cell_jet(c.ci, c.cj, c.uv);
  const double a = double(ns_ - 1), b = double(nt_ - 1);
  s.su *= a, s.sv *= b, s.suu *= a * a, s.suv *= a * b, s.svv *= b * b;
  return s;
}

void CoonsNetworkPatch::influence(std::size_t k, std::span<const Vec2> xs,
                                  std::span<Jet> out) const {
  assert(k < size() && xs.size() == out.size());
  const std::size_t node = k / 4, i = node / nt_, j = node % nt_;
  std::array<Jet, 16> local;
  for (std::size_t s = 0; s < xs.size(); ++s) {
    out[s] = Jet(0.0);
    const Cell c = locate(xs[s]);
    if (i < c.ci || i > c.ci + 1 || j < c.cj || j > c.cj + 1) continue;  // node not on this cell
    coons_cell_basis(c.uv, cell_lengths(c.ci, c.cj), local);
    const int l = static_cast<int>(((i - c.ci) * 2 + (j - c.cj)) * 4 + k % 4);
    out[s] = to_domain(local[l], double(ns_ - 1), double(nt_ - 1));
  }
}

std::vector<BezierCurve> CoonsNetworkPatch::boundary_curves() const {
  const auto P = [&](std::size_t i, std::size_t j, int q) {
    return points_[(i * nt_ + j) * 4 + q];
  };
  const std::size_t I = ns_ - 1, J = nt_ - 1;
  std::vector<BezierCurve> sides;
  if (ns_ == 2 && nt_ == 2) {  // one cell: every side is its Hermite boundary cubic
    const CellLengths L = cell_lengths(0, 0);
    sides.push_back(
        HermiteCurve(P(0, 0, 0), P(1, 0, 0), L.S0 * P(0, 0, 1), L.S0 * P(1, 0, 1)).to_bezier());
    sides.push_back(
        HermiteCurve(P(1, 0, 0), P(1, 1, 0), L.T1 * P(1, 0, 2), L.T1 * P(1, 1, 2)).to_bezier());
    sides.push_back(
        HermiteCurve(P(1, 1, 0), P(0, 1, 0), -L.S1 * P(1, 1, 1), -L.S1 * P(0, 1, 1)).to_bezier());
    sides.push_back(
        HermiteCurve(P(0, 1, 0), P(0, 0, 0), -L.T0 * P(0, 1, 2), -L.T0 * P(0, 0, 2)).to_bezier());
    return sides;
  }
  std::vector<Vec3> s0, s1, s2, s3;
  for (std::size_t i = 0; i <= I; ++i) s0.push_back(P(i, 0, 0)), s2.push_back(P(I - i, J, 0));
  for (std::size_t j = 0; j <= J; ++j) s1.push_back(P(I, j, 0)), s3.push_back(P(0, J - j, 0));
  return {BezierCurve(s0), BezierCurve(s1), BezierCurve(s2), BezierCurve(s3)};
}

Vec3 CoonsNetworkPatch::boundary_point(int side, double t) const {
  const auto P = [&](std::size_t i, std::size_t j, int q) {
    return points_[(i * nt_ + j) * 4 + q];
  };
  // The cell a side coordinate x in [0,1] falls in among n cells, and its local parameter.
  const auto split = [](double x, std::size_t n) {
    const std::size_t c =
        std::min(n - 1, static_cast<std::size_t>(std::max(0.0, std::floor(x * double(n)))));
    return std::pair<std::size_t, double>(c, x * double(n) - double(c));
  };
  const std::size_t I = ns_ - 1, J = nt_ - 1;
  const Vec2 x = domain_.side_point(side, t);
  if (side == 0 || side == 2) {  // a row: cubics in s scaled by the cell's bottom/top length
    const std::size_t j = side == 0 ? 0 : J;
    const auto [ci, a] = split(x.x, I);
    const CellLengths L = cell_lengths(ci, side == 0 ? 0 : J - 1);
    const double S = side == 0 ? L.S0 : L.S1;
    return HermiteCurve(P(ci, j, 0), P(ci + 1, j, 0), S * P(ci, j, 1), S * P(ci + 1, j, 1))
        .evaluate(a)
        .p;
  }
  const std::size_t i = side == 1 ? I : 0;  // a column: cubics in t, right/left lengths
  const auto [cj, b] = split(x.y, J);
  const CellLengths L = cell_lengths(side == 1 ? I - 1 : 0, cj);
  const double T = side == 1 ? L.T1 : L.T0;
  return HermiteCurve(P(i, cj, 0), P(i, cj + 1, 0), T * P(i, cj, 2), T * P(i, cj + 1, 2))
      .evaluate(b)
      .p;
}

}  // namespace pl
