// A simple polygon domain (counter-clockwise, convex or not), for GB patches whose boundary is
// concave. Side i runs from vertex i-1 (t = 0) to vertex i (t = 1), as in ConvexPolygonDomain.
// Tessellated by a constrained Delaunay triangulation of the side samples and a triangular grid
// of interior points.
#pragma once

#include <vector>

#include "core/domain/domain.hpp"

namespace pl {

class ConcavePolygonDomain : public Domain {
 public:
  // Throws std::invalid_argument unless the vertices form a simple counter-clockwise polygon
  // with at least 3 vertices and no zero-length side.
  explicit ConcavePolygonDomain(std::vector<Vec2> vertices);

  const std::vector<Vec2>& vertices() const { return vertices_; }
  const Vec2& vertex(int i) const;  // index taken modulo n
  double area() const;
  int side_count() const override { return static_cast<int>(vertices_.size()); }
  Vec2 side_point(int side, double t) const override;
  Vec2 interior_point() const override { return interior_; }
  std::string key() const override;
  Tessellation tessellate(int density) const override;

 private:
  std::vector<Vec2> vertices_;
  Vec2 interior_;
};

// Distance from x to the segment ab.
double segment_distance(Vec2 x, Vec2 a, Vec2 b);

}  // namespace pl
