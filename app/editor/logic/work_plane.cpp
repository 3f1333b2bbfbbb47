#include "app/editor/logic/work_plane.hpp"

#include <cmath>

namespace pl {

const char* work_plane_name(WorkPlaneKind kind) {
  switch (kind) {
    case WorkPlaneKind::View:
      return "View";
    case WorkPlaneKind::XY:
      return "XY";
    case WorkPlaneKind::XZ:
      return "XZ";
    case WorkPlaneKind::YZ:
      return "YZ";
  }
  return "?";
}

PlaneFrame WorkPlane::frame(const Camera& camera) const {
  PlaneFrame f;
  f.origin = origin;
  switch (kind) {
    case WorkPlaneKind::View:
      f.u = camera.right();
      f.v = camera.up();
      f.normal = -camera.forward();
      break;
    case WorkPlaneKind::XY:
      f.u = Vec3(1, 0, 0), f.v = Vec3(0, 1, 0), f.normal = Vec3(0, 0, 1);
      break;
    case WorkPlaneKind::XZ:
      f.u = Vec3(1, 0, 0), f.v = Vec3(0, 0, 1), f.normal = Vec3(0, -1, 0);
      break;
    case WorkPlaneKind::YZ:
      f.u = Vec3(0, 1, 0), f.v = Vec3(0, 0, 1), f.normal = Vec3(1, 0, 0);
      break;
  }
  return f;
}

std::optional<Vec3> WorkPlane::hit(const Camera& camera, const Ray& ray) const {
  return intersect_plane_ahead(ray, frame(camera));
}

std::optional<Vec3> intersect_plane_ahead(const Ray& ray, const PlaneFrame& plane) {
  const double denom = glm::dot(ray.direction, plane.normal);
  // Parallel, within rounding of a unit direction against a unit normal.
  if (std::abs(denom) < 1e-12) return std::nullopt;
  const double t = glm::dot(plane.origin - ray.origin, plane.normal) / denom;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  return ray.origin + t * ray.direction;
}

double grid_step(double world_size, int cells) {
  if (!(world_size > 0) || cells <= 0 || !std::isfinite(world_size)) return 1.0;
  const double raw = world_size / cells;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

double shown_grid_step(const Camera& camera) {
  return grid_step(2 * camera.half_height(), kGridCellsPerView);
}

Vec3 nearest_grid_point(const PlaneFrame& f, const Vec3& p, double step) {
  const Vec2 c = plane_coordinates(f, p);
  return f.origin + std::round(c.x / step) * step * f.u + std::round(c.y / step) * step * f.v;
}

std::vector<Vec3> grid_segments(const PlaneFrame& f, const Vec3& centre, double step,
                                int half_cells) {
  std::vector<Vec3> s;
  if (!(step > 0) || half_cells <= 0) return s;
  const Vec2 c = plane_coordinates(f, centre);
  const double cu = std::round(c.x / step) * step, cv = std::round(c.y / step) * step;
  auto at = [&](double a, double b) { return f.origin + a * f.u + b * f.v; };
  s.reserve(std::size_t(8) * half_cells * (2 * half_cells + 1));
  for (int i = -half_cells; i <= half_cells; ++i)
    for (int j = -half_cells; j < half_cells; ++j) {
      // One segment per cell side: the renderer drops a segment with an end behind the eye,
      // so long lines through the view would vanish whole.
      s.push_back(at(cu + i * step, cv + j * step));
      s.push_back(at(cu + i * step, cv + (j + 1) * step));
      s.push_back(at(cu + j * step, cv + i * step));
      s.push_back(at(cu + (j + 1) * step, cv + i * step));
    }
  return s;
}

Vec2 plane_coordinates(const PlaneFrame& f, const Vec3& p) {
  const Vec3 d = p - f.origin;
  return Vec2(glm::dot(d, f.u), glm::dot(d, f.v));
}

}  // namespace pl
