// A grid network of ns x nt nodes filled with the Coons cells of coons_cell.hpp: one Patch over
// [0,1]^2 split into (ns-1) x (nt-1) equal cells (cell (ci, cj) covers
// [ci/(ns-1), (ci+1)/(ns-1)] x [cj/(nt-1), (cj+1)/(nt-1)]).
//
// Control data, 4 vectors per node (i along s/u, j along t/v), points[(i*nt + j)*4 + q]:
// q = 0: r, 1: r_s, 2: r_t, 3: r_st. Parameters: s[j][i] is node (i, j)'s s on row j and
// t[i][j] its t on column i; each row and column may be spaced differently, so opposite cell
// boundaries have different parametric lengths (a non-rectangular network). Lengths::Equal is
// the common simplification: every boundary gets the same length (the mean spacing of its
// direction), which causes flat spots and wiggles on unequal spacing.
#pragma once

#include "core/patch/coons_cell.hpp"
#include "core/patch/unit_square_patch.hpp"

namespace pl {

class CoonsNetworkPatch final : public UnitSquarePatch<CoonsNetworkPatch> {
 public:
  static constexpr const char* kType = "coons-network";  // the scene-format type name
  enum class Lengths { Network, Equal };

  // Throws std::invalid_argument for fewer than 2 x 2 nodes, wrong counts, or parameters that
  // do not increase strictly along every row and column.
  CoonsNetworkPatch(std::size_t ns, std::size_t nt, std::vector<std::vector<double>> s,
                    std::vector<std::vector<double>> t, std::vector<Vec3> data,
                    Lengths lengths = Lengths::Network);

  ControlPointKind kind(std::size_t k) const override;
  void basis(Vec2 x, std::span<Jet> out) const override;
  SurfaceJet evaluate(Vec2 x) const override;
  void influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const override;
  // Exact for a one-cell side (a Hermite cubic); a multi-cell side is piecewise cubic, returned
  // as the Bézier curve on its node positions (same end points; the interface has no piecewise
  // curve).
  std::vector<BezierCurve> boundary_curves() const override;
  // The side's own piecewise Hermite cubic (each cell's boundary curve of its own length) at the
  // side parameter, exact for any number of cells.
  Vec3 boundary_point(int side, double t) const override;

  std::size_t ns() const { return ns_; }
  std::size_t nt() const { return nt_; }
  Lengths lengths() const { return lengths_; }
  const std::vector<std::vector<double>>& s() const { return s_; }
  const std::vector<std::vector<double>>& t() const { return t_; }
  CellLengths cell_lengths(std::size_t ci, std::size_t cj) const;
  // Cell (ci, cj) at its local (u, v) in [0,1]^2, derivatives in the local parameters: what
  // the continuity tests compare across internal edges.
  SurfaceJet cell_jet(std::size_t ci, std::size_t cj, Vec2 uv) const;

 private:
  struct Cell {
    std::size_t ci, cj;
    Vec2 uv;
  };
  Cell locate(Vec2 x) const;
  std::size_t data_index(std::size_t ci, std::size_t cj,
                         int local) const;  // local: coons_cell order

  std::size_t ns_, nt_;
  std::vector<std::vector<double>> s_, t_;
  Lengths lengths_;
  double mean_s_ = 1, mean_t_ = 1;
};

}  // namespace pl
