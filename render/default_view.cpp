#include "render/default_view.hpp"

#include <cmath>

namespace pl {

namespace {

// The iso preset's eye direction: from (+x, -y), 35.26 degrees up.
Vec3 iso_direction() {
  return -preset_camera(ViewPreset::Iso, Box(), 1.0).forward();
}

// The iso view is kept while it sees the front within 75 degrees of the mean normal (a patch
// lying in the xy plane is seen at 55 degrees), or when the surfaces have no clear front (closed
// or strongly curved: the mean normal is short).
constexpr double kIsoKeptCos = 0.25;
constexpr double kOneSided = 0.25;
// The front view is tilted this far towards the iso direction.
constexpr double kTiltRadians = 15.0 * 3.14159265358979323846 / 180.0;

}  // namespace

Vec3 mean_normal(std::span<const SurfaceMesh* const> meshes) {
  Vec3 sum(0.0);
  double area = 0;
  for (const SurfaceMesh* m : meshes)
    for (const auto& t : m->triangles) {
      const Vec3 a = m->positions[t[0]], b = m->positions[t[1]], c = m->positions[t[2]];
      // |cross| is twice the area: the sum of cross products weighs unit normals by area.
      // Triangles follow the surface's orientation (S_u x S_v), so this is the front's normal.
      const Vec3 n = glm::cross(b - a, c - a);
      const double len = glm::length(n);
      if (!(len > 0) || !std::isfinite(len)) continue;
      sum += n;
      area += len;
    }
  return area > 0 ? sum / area : Vec3(0.0);
}

Vec3 default_view_direction(std::span<const SurfaceMesh* const> meshes) {
  const Vec3 iso = iso_direction();
  const Vec3 m = mean_normal(meshes);
  const double len = glm::length(m);
  if (len < kOneSided) return iso;
  const Vec3 n = m / len;
  if (glm::dot(iso, n) >= kIsoKeptCos) return iso;
  // Tilt the front view towards the iso direction (or, when iso is straight behind, towards z).
  Vec3 t = iso - glm::dot(iso, n) * n;
  if (glm::length(t) < 1e-6) t = Vec3(0, 0, 1) - n.z * n;
  if (glm::length(t) < 1e-6) return n;
  return glm::normalize(n + std::tan(kTiltRadians) * glm::normalize(t));
}

std::vector<Vec3> framing_points(std::span<const DrawScene* const> scenes) {
  std::vector<Vec3> points;
  for (const DrawScene* d : scenes) {
    for (const SurfaceMesh& m : d->surfaces)
      for (const Vec3& p : m.positions)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) points.push_back(p);
    points.insert(points.end(), d->net.points.begin(), d->net.points.end());
    for (const Arrow& a : d->arrows) {
      points.push_back(a.base);
      points.push_back(a.tip);
    }
    for (const Polyline& l : d->network_curves) points.insert(points.end(), l.begin(), l.end());
  }
  return points;
}

Camera default_camera(std::span<const DrawScene* const> scenes, double aspect) {
  std::vector<const SurfaceMesh*> meshes;
  for (const DrawScene* d : scenes)
    for (const SurfaceMesh& m : d->surfaces) meshes.push_back(&m);
  const Vec3 d = default_view_direction(meshes);
  Camera c;
  c.yaw = std::atan2(d.y, d.x);
  c.pitch = std::asin(std::clamp(d.z, -1.0, 1.0));
  c.frame_points(framing_points(scenes), aspect);
  return c;
}

}  // namespace pl
