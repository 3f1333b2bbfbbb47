#include "render/default_view.hpp"

#include <algorithm>
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
// The front view is tilted this far off the mean normal, so the shape reads in depth.
constexpr double kTiltRadians = 15.0 * 3.14159265358979323846 / 180.0;
// Directions of the tilt tried around the normal, and the most triangles measured per try.
constexpr int kTiltDirections = 24;
constexpr std::size_t kMeasuredTriangles = 20000;

Vec3 direction_of(const Camera& c) {
  return -c.forward();
}

Camera looking_from(const Vec3& d) {
  Camera c;
  c.yaw = std::atan2(d.y, d.x);
  c.pitch = std::asin(std::clamp(d.z, -1.0, 1.0));
  return c;
}

// The share of the view covered by the front faces of the meshes (overlaps counted twice, which
// a patch seen from its front rarely has), measured on at most kMeasuredTriangles triangles.
double front_coverage(std::span<const SurfaceMesh* const> meshes, const Camera& c, double aspect) {
  const glm::dmat4 vp = c.projection(aspect) * c.view();
  std::size_t total = 0;
  for (const SurfaceMesh* m : meshes) total += m->triangles.size();
  const std::size_t step = std::max<std::size_t>(1, total / kMeasuredTriangles);
  double area = 0;  // in NDC units: the view is 2 x 2
  std::size_t k = 0;
  for (const SurfaceMesh* m : meshes)
    for (const auto& t : m->triangles) {
      if (k++ % step) continue;
      glm::dvec2 q[3];
      bool in_front = true;
      for (int i = 0; i < 3; ++i) {
        const glm::dvec4 p = vp * glm::dvec4(m->positions[t[i]], 1.0);
        in_front &= p.w > 0;
        q[i] = glm::dvec2(p) / p.w;
      }
      if (!in_front) continue;
      const glm::dvec2 a = q[1] - q[0], b = q[2] - q[0];
      area += std::max(0.0, 0.5 * (a.x * b.y - a.y * b.x)) * double(step);
    }
  return area / 4.0;
}

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

std::optional<Vec3> facing_direction(std::span<const SurfaceMesh* const> meshes) {
  const Vec3 m = mean_normal(meshes);
  const double len = glm::length(m);
  if (len < kOneSided) return std::nullopt;
  const Vec3 n = m / len;
  if (glm::dot(iso_direction(), n) >= kIsoKeptCos) return std::nullopt;
  return n;
}

Vec3 default_view_direction(std::span<const SurfaceMesh* const> meshes) {
  const Camera c = default_camera_of(meshes, {}, 4.0 / 3.0);
  return direction_of(c);
}

void append_comb_tips(const DrawScene& d, const DisplaySettings& settings, std::vector<Vec3>& out) {
  std::vector<const CurvatureComb*> combs;
  for (const auto* list : {&d.network_combs, &d.border_combs, &d.free_curve_combs})
    for (const CurvatureComb& c : *list) combs.push_back(&c);
  const Box box = d.bounds();
  const double diagonal = box.empty() ? 0.0 : glm::length(box.hi - box.lo);
  // As GpuScene and SceneRenderer::draw_combs size the teeth.
  const double scale =
      settings.comb_length.value_or(automatic_comb_scale_of(combs, diagonal)) * settings.comb_scale;
  const double cap = kCombCap * kDefaultCombFraction * diagonal * settings.comb_scale;
  if (scale > 0) append_tooth_tips(combs, scale, cap, out);
}

void append_tooth_tips(std::span<const CurvatureComb* const> combs, double scale, double cap,
                       std::vector<Vec3>& out) {
  for (const CurvatureComb* c : combs)
    for (std::size_t i = 0; i < c->teeth.size() && i < c->points.size(); ++i) {
      Vec3 tooth = scale * c->teeth[i];
      const double len = glm::length(tooth);
      if (!std::isfinite(len)) continue;
      if (cap > 0 && len > cap) tooth *= cap / len;
      out.push_back(c->points[i] + tooth);
    }
}

std::vector<Vec3> framing_points(std::span<const DrawScene* const> scenes,
                                 const DisplaySettings* settings) {
  std::vector<Vec3> points;
  for (const DrawScene* d : scenes) {
    for (const SurfaceMesh& m : d->surfaces)
      for (const Vec3& p : m.positions)
        if (finite(p)) points.push_back(p);
    points.insert(points.end(), d->net.points.begin(), d->net.points.end());
    for (const Arrow& a : d->arrows) {
      points.push_back(a.base);
      points.push_back(a.tip);
    }
    for (const Polyline& l : d->network_curves) points.insert(points.end(), l.begin(), l.end());
    for (const Polyline& l : d->free_curves) points.insert(points.end(), l.begin(), l.end());
    if (settings && settings->combs) append_comb_tips(*d, *settings, points);
  }
  return points;
}

Camera default_camera_of(std::span<const SurfaceMesh* const> meshes, std::span<const Vec3> points,
                         double aspect) {
  std::vector<Vec3> own;
  if (points.empty()) {  // frame the meshes themselves
    for (const SurfaceMesh* m : meshes)
      own.insert(own.end(), m->positions.begin(), m->positions.end());
    points = own;
  }
  const std::optional<Vec3> front = facing_direction(meshes);
  if (!front) {
    Camera c = looking_from(iso_direction());
    c.frame_points(points, aspect);
    return c;
  }
  // Around the normal, the tilt under which the front fills the most of the view (a long patch
  // lies along the frame's long side).
  const Vec3 n = *front;
  const Vec3 e1 = glm::normalize(std::abs(n.z) < 0.9 ? glm::cross(n, Vec3(0, 0, 1))
                                                     : glm::cross(n, Vec3(1, 0, 0)));
  const Vec3 e2 = glm::cross(n, e1);
  Camera best;
  double best_coverage = -1;
  for (int k = 0; k < kTiltDirections; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / kTiltDirections;
    const Vec3 t = std::cos(a) * e1 + std::sin(a) * e2;
    Camera c = looking_from(glm::normalize(n + std::tan(kTiltRadians) * t));
    c.frame_points(points, aspect);
    const double coverage = front_coverage(meshes, c, aspect);
    if (coverage > best_coverage + 1e-9) best = c, best_coverage = coverage;
  }
  return best;
}

Camera default_camera(std::span<const DrawScene* const> scenes, double aspect,
                      const DisplaySettings* settings) {
  std::vector<const SurfaceMesh*> meshes;
  for (const DrawScene* d : scenes)
    for (const SurfaceMesh& m : d->surfaces) meshes.push_back(&m);
  return default_camera_of(meshes, framing_points(scenes, settings), aspect);
}

}  // namespace pl
