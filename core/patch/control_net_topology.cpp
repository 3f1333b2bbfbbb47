#include "core/patch/control_net_topology.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/patch/gb/default_net.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

using Segment = std::array<uint32_t, 2>;

uint32_t u32(std::size_t i) {
  return static_cast<uint32_t>(i);
}

// Segments with the smaller index first, each once, loops (a point joined to itself, e.g. a
// collapsed GB corner block position) dropped.
std::vector<Segment> normalised(std::vector<Segment> s) {
  for (Segment& e : s)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::erase_if(s, [](const Segment& e) { return e[0] == e[1]; });
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

ControlNetTopology positions_only(std::size_t size, std::vector<Segment> segments) {
  ControlNetTopology t;
  t.segments = normalised(std::move(segments));
  t.is_vector.assign(size, false);
  return t;
}

}  // namespace

std::vector<Segment> grid_segments(std::size_t nu, std::size_t nv, uint32_t first) {
  std::vector<Segment> s;
  auto id = [&](std::size_t i, std::size_t j) { return first + u32(i * nv + j); };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      if (i + 1 < nu) s.push_back({id(i, j), id(i + 1, j)});
      if (j + 1 < nv) s.push_back({id(i, j), id(i, j + 1)});
    }
  return s;
}

ControlNetTopology net_of(const BezierPatch& p) {
  return positions_only(p.size(), grid_segments(p.degree_u() + 1, p.degree_v() + 1));
}

ControlNetTopology net_of(const BSplinePatch& p) {
  return positions_only(p.size(), grid_segments(p.grid().nu(), p.grid().nv()));
}

ControlNetTopology net_of(const NurbsPatch& p) {
  return positions_only(p.size(), grid_segments(p.grid().nu(), p.grid().nv()));
}

ControlNetTopology net_of(const InterpolatingPatch& p) {
  return positions_only(p.size(), grid_segments(4, 4));
}

ControlNetTopology net_of(const PairJoinPatch& p) {
  return positions_only(p.size(), grid_segments(p.aux_degree_u() + 1, p.aux_degree_v() + 1));
}

ControlNetTopology net_of(const GapFillPatch& p) {
  std::vector<Segment> s = grid_segments(p.q().grid().nu(), p.q().grid().nv());
  const std::vector<Segment> r =
      grid_segments(p.r().grid().nu(), p.r().grid().nv(), u32(p.q().size()));
  s.insert(s.end(), r.begin(), r.end());
  return positions_only(p.size(), std::move(s));
}

ControlNetTopology net_of(const HermitePatch& p) {
  // points[a * 4 + b] = Q_ab: r(i, j) at (i, j), r_u(i, j) at (2 + i, j), r_v(i, j) at (i, 2 + j),
  // r_uv(i, j) at (2 + i, 2 + j).
  auto at = [](int a, int b) { return u32(a * 4 + b); };
  ControlNetTopology t = positions_only(
      p.size(),
      {{at(0, 0), at(1, 0)}, {at(1, 0), at(1, 1)}, {at(1, 1), at(0, 1)}, {at(0, 1), at(0, 0)}});
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      t.arrows.push_back({at(i, j), at(2 + i, j), 1.0 / 3, ArrowKind::Tangent});
      t.arrows.push_back({at(i, j), at(i, 2 + j), 1.0 / 3, ArrowKind::Tangent});
      t.arrows.push_back({at(i, j), at(2 + i, 2 + j), 1.0 / 9, ArrowKind::Twist});
      t.is_vector[at(2 + i, j)] = t.is_vector[at(i, 2 + j)] = t.is_vector[at(2 + i, 2 + j)] = true;
    }
  return t;
}

ControlNetTopology net_of(const CoonsNetworkPatch& p) {
  const std::size_t ns = p.ns(), nt = p.nt();
  auto node = [&](std::size_t i, std::size_t j, int q) { return u32((i * nt + j) * 4 + q); };
  std::vector<Segment> s;
  for (const Segment& e : grid_segments(ns, nt)) s.push_back({e[0] * 4, e[1] * 4});
  ControlNetTopology t = positions_only(p.size(), std::move(s));
  // The mean spacing of a node's neighbours along one parameter line (s[j][i] on row j).
  auto spacing = [](const std::vector<double>& line, std::size_t i) {
    double sum = 0;
    int count = 0;
    if (i > 0) sum += line[i] - line[i - 1], ++count;
    if (i + 1 < line.size()) sum += line[i + 1] - line[i], ++count;
    return sum / count;
  };
  for (std::size_t i = 0; i < ns; ++i)
    for (std::size_t j = 0; j < nt; ++j) {
      const double ds = spacing(p.s()[j], i), dt = spacing(p.t()[i], j);
      t.arrows.push_back({node(i, j, 0), node(i, j, 1), ds / 3, ArrowKind::Tangent});
      t.arrows.push_back({node(i, j, 0), node(i, j, 2), dt / 3, ArrowKind::Tangent});
      t.arrows.push_back({node(i, j, 0), node(i, j, 3), ds * dt / 9, ArrowKind::Twist});
      for (int q = 1; q < 4; ++q) t.is_vector[node(i, j, q)] = true;
    }
  return t;
}

namespace {

// The Gregory patches' shared structure: per side a boundary row of `row` points, two twins.
template <class P>
ControlNetTopology gregory_like(const P& p, int sides, int row, bool zigzag) {
  std::vector<Segment> s;
  for (int side = 0; side < sides; ++side) {
    auto b = [&](int j) { return u32(P::boundary_index(side, j)); };
    auto twin = [&](int k) { return u32(P::twin_index(side, k)); };
    for (int j = 0; j + 1 < row; ++j) s.push_back({b(j), b(j + 1)});
    s.push_back({twin(0), twin(1)});
    // The twins pull on the boundary points next to them (quad: like a bicubic net's inner
    // points; triangle: a quartic triangle's net, each inner point joined to two boundary points).
    s.push_back({b(1), twin(0)});
    s.push_back({b(row - 2), twin(1)});
    if (zigzag) {
      s.push_back({twin(0), b(2)});
      s.push_back({b(2), twin(1)});
    }
    // The two twins of this side's start corner: one Bézier point split in two.
    s.push_back({twin(0), u32(P::twin_index((side + sides - 1) % sides, 1))});
  }
  return positions_only(p.size(), std::move(s));
}

}  // namespace

ControlNetTopology net_of(const GregoryQuadPatch& p) {
  return gregory_like(p, 4, 4, false);
}

ControlNetTopology net_of(const GregoryTriPatch& p) {
  return gregory_like(p, 3, 5, true);
}

namespace {

// The net lines of a .gbp net of n sides and degree d (index: gb_net_index).
std::vector<Segment> gbp_net_segments(int n, int d) {
  const int l = (d + 1) / 2;
  std::vector<Segment> s;
  for (int i = 0; i < n; ++i) {
    auto at = [&](int j, int k) { return u32(gb_net_index(n, d, i, j, k)); };
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        if (j < d) s.push_back({at(j, k), at(j + 1, k)});      // rows
        if (k + 1 < l) s.push_back({at(j, k), at(j, k + 1)});  // spokes
      }
    // The middle of the innermost row leads to the central point (both middle points for odd d;
    // they are the neighbours' too, so each is joined once).
    s.push_back({at(d / 2, l - 1), 0});
    s.push_back({at((d + 1) / 2, l - 1), 0});
  }
  return s;
}

}  // namespace

ControlNetTopology net_of(const GBPatch& p) {
  return positions_only(p.size(), gbp_net_segments(p.sides(), p.degree()));
}

ControlNetTopology net_of(const GBInteriorPatch& p) {
  ControlNetTopology t = positions_only(p.size(), gbp_net_segments(p.sides(), p.degree()));
  for (std::size_t k = p.net_size(); k < p.size(); ++k) t.is_vector[k] = true;  // not drawn
  return t;
}

ControlNetTopology net_of(const GBRibbonPatch& p) {
  std::vector<Segment> s;
  for (int i = 0; i < p.sides(); ++i) {
    const int d = p.degree(i), l = p.layers(i);
    for (int k = 0; k < l; ++k)
      for (int j = 0; j <= d; ++j) {
        if (j < d) s.push_back({u32(p.index(i, j, k)), u32(p.index(i, j + 1, k))});
        if (k + 1 < l) s.push_back({u32(p.index(i, j, k)), u32(p.index(i, j, k + 1))});
      }
  }
  return positions_only(p.size(), std::move(s));
}

// An explicit-ribbon patch: each side's curve as a polyline of positions; its cross derivative's
// control vectors are vectors, not positions. Where the curve and the cross derivative are Bézier
// curves of one degree d (every network face, and most files), vector j is drawn as an arrow from
// the curve's point j to P_j + D_j / d, the ribbon's inner Bézier row (the Chiyokura–Kimura inner
// points of a network face); otherwise the vectors are not drawn.
ControlNetTopology net_of(const RibbonPatch& p) {
  ControlNetTopology t;
  t.is_vector.assign(p.size(), false);
  std::vector<Segment> s;
  std::size_t k = 0;
  for (const RibbonSide& side : p.sides()) {
    const std::size_t curve = k, nc = side.curve.points.size();
    const std::size_t cross = curve + nc, nx = side.cross.points.size();
    k = cross + nx;
    for (std::size_t j = 0; j + 1 < nc; ++j) s.push_back({u32(curve + j), u32(curve + j + 1)});
    const bool arrows = side.curve.type == CurveType::Bezier &&
                        side.cross.type == CurveType::Bezier && nc == nx && nc >= 2;
    for (std::size_t j = 0; j < nx; ++j) {
      t.is_vector[cross + j] = true;
      if (arrows)
        t.arrows.push_back(
            {u32(curve + j), u32(cross + j), 1.0 / double(nc - 1), ArrowKind::Tangent});
    }
  }
  t.segments = normalised(std::move(s));
  return t;
}

ControlNetTopology net_of(const CatmullClarkPatch& p) {
  std::vector<Segment> s;
  for (const std::vector<int>& face : p.limit().faces())
    for (std::size_t k = 0; k < face.size(); ++k)
      s.push_back({u32(face[k]), u32(face[(k + 1) % face.size()])});
  return positions_only(p.size(), std::move(s));
}

ControlNetTopology control_net_topology(const Patch& patch) {
  // One net_of overload per registered type (patch_types.hpp): a type without one does not
  // compile here.
  return visit_patch_type(patch, [](const auto& p) { return net_of(p); });
}

Vec3 arrow_tip(const Patch& patch, const DerivativeArrow& arrow) {
  return patch.control_point(arrow.base) + arrow.scale * patch.control_point(arrow.vector);
}

}  // namespace pl
