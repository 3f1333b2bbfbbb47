// A convex polygon domain (counter-clockwise vertices), tessellated in rings around its centroid.
// Side i runs from vertex i-1 (t = 0) to vertex i (t = 1), the convention of the GB papers and
// of the transfinite library.
#pragma once

#include <vector>

#include "core/domain/domain.hpp"

namespace pl {

class ConvexPolygonDomain : public Domain {
 public:
  // Throws std::invalid_argument unless the vertices form a strictly convex CCW polygon.
  explicit ConvexPolygonDomain(std::vector<Vec2> vertices);
  // The regular n-gon as transfinite defines it: [-1,1]^2 for n = 4, otherwise the n-gon
  // inscribed in the unit circle with v_i = (cos(a i), sin(a i)), a = 2 pi / n.
  static ConvexPolygonDomain regular(int n);

  const std::vector<Vec2>& vertices() const { return vertices_; }
  const Vec2& vertex(int i) const;  // index taken modulo n
  int side_count() const override { return static_cast<int>(vertices_.size()); }
  Vec2 side_point(int side, double t) const override;
  Vec2 interior_point() const override { return centre_; }
  std::string key() const override;
  Tessellation tessellate(int density) const override;

 private:
  std::vector<Vec2> vertices_;
  Vec2 centre_;
};

}  // namespace pl
