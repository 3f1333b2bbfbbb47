// The local parameters (s_i, d_i) of a point of a convex polygonal domain with respect to each of
// its sides, as the ribbon-based schemes use them (Salvi, Varady, Rockwood, "Ribbon-based
// transfinite surfaces", CAGD 31 (2014), section 3; Salvi et al., "Computationally efficient
// transfinite patches with fullness control", arXiv:2002.11212). s_i runs along side i (0 at its
// start vertex v_{i-1}, 1 at v_i) and d_i grows away from it (0 on the side). Every value is a
// Jet in the domain point (u, v), so the schemes' derivatives are exact.
#pragma once

#include <utility>
#include <vector>

#include "core/math/jet.hpp"
#include "core/math/vec.hpp"

namespace pl::transfinite {

struct SideParameters {
  std::vector<Jet> s, d;  // one per side
};

class PolygonParameters {
 public:
  // vertices: counter-clockwise, strictly convex; side i runs from vertices[i-1] to vertices[i].
  // centre: a point inside (it orients each side's inward normal).
  PolygonParameters(std::vector<Vec2> vertices, Vec2 centre);

  int size() const { return static_cast<int>(v_.size()); }
  const Vec2& vertex(int i) const { return v_[wrap(i)]; }
  const Vec2& centre() const { return centre_; }

  // Bilinear: s_i from the quadrilateral spanned by side i and its two neighbouring sides
  // (the root of a quadratic), d_i the matching height. Corner-based, elastic.
  SideParameters bilinear(Vec2 x) const;
  // Parallel: the bilinear s_i, d_i the distance from side i's line scaled so that the farthest
  // vertex is at 1. Side-based.
  SideParameters parallel(Vec2 x) const;
  // Interconnected: the bilinear s_i and d_i = (1 - s_{i-1}) H(s_i) + s_{i+1} (1 - H(s_i)), the
  // neighbours' s as distances. Generalized Coons.
  SideParameters interconnected(Vec2 x) const;
  // Barycentric: Wachspress coordinates lambda; s_i = lambda_i / (lambda_{i-1} + lambda_i),
  // d_i = 1 - lambda_{i-1} - lambda_i. Composite ribbon, midpoint.
  SideParameters barycentric(Vec2 x) const;
  // Constrained barycentric: the barycentric d_i blended with the neighbours' s so that it
  // behaves like a distance near every side. Midpoint Coons.
  SideParameters constrained_barycentric(Vec2 x) const;

  // The Wachspress coordinates alone (in the rounding order of the reference library).
  std::vector<Jet> wachspress(Vec2 x) const;

 private:
  int wrap(int i) const {
    const int n = size();
    return ((i % n) + n) % n;
  }
  Jet bilinear_s(int i, const Jet& u, const Jet& v) const;
  Jet bilinear_d(int i, const Jet& u, const Jet& v, const Jet& s) const;
  // local(i, (u, v) - origin) as Jets.
  std::pair<Jet, Jet> local_point(int i, const Jet& u, const Jet& v, Vec2 origin) const;
  // (w . du_i, w . dv_i) / |du_i|^2 for a constant vector w.
  Vec2 local(int i, Vec2 w) const;

  std::vector<Vec2> v_;
  Vec2 centre_;
  std::vector<Vec2> du_, dv_;  // per side: direction and inward normal (same length)
  std::vector<double> parallel_scale_;
  std::vector<double> sin_angle_;  // sine of the interior angle at each vertex
};

}  // namespace pl::transfinite
