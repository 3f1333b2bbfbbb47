#include "core/analysis/scene_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>

namespace pl {

namespace {

// The curve side s of the surface must interpolate, as a function of the side parameter: the
// network edge (independent of the patch) for faces, the patch's defining boundary curve for
// explicit patches.
std::function<Vec3(double)> side_curve(const Scene& scene, const SceneSurface& s, int face_side,
                                       int patch_side) {
  const Patch& patch = s.evaluator->patch();
  if (s.face < 0)
    return [&patch, patch_side](double t) { return patch.boundary_point(patch_side, t); };
  const Network& net = *scene.network;
  const auto& loop = net.faces[s.face].loop;
  const int n = static_cast<int>(loop.size());
  const int a = loop[face_side], b = loop[(face_side + 1) % n];
  for (std::size_t e = 0; e < net.edges.size(); ++e) {
    const bool forward = net.edges[e].v[0] == a && net.edges[e].v[1] == b;
    if (forward || (net.edges[e].v[0] == b && net.edges[e].v[1] == a)) {
      BezierCurve c = forward ? net.edge_curve(int(e)) : net.edge_curve(int(e)).reversed();
      return [c = std::move(c)](double t) { return c.point(t); };
    }
  }
  // Unreachable after validate_network: every face side has its edge.
  return [&patch, patch_side](double t) { return patch.boundary_point(patch_side, t); };
}

}  // namespace

PatchReport analyze_surface(const Scene& scene, const SceneSurface& s) {
  const PatchEvaluator& ev = *s.evaluator;
  PatchReport r;
  r.name = s.name;
  r.type = ev.patch().type();
  r.sides = ev.patch().domain().side_count();
  if (s.face >= 0 && scene.network && r.type.rfind("gb-ribbons", 0) == 0) {
    const NetworkFace& face = scene.network->faces.at(s.face);
    r.degree = face.degree;
    r.offsets = face.offsets.size();
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  r.gaussian = {inf, -inf};
  r.mean = {inf, -inf};
  for (std::size_t i = 0; i < ev.sample_count(); ++i) {
    const SurfaceGeometry& g = ev.geometry()[i];
    if (!ev.finite(i)) {
      ++r.nonfinite_samples;
      continue;
    }
    if (g.status == GeometryStatus::Singular) ++r.singular_samples;
    r.gaussian = {std::min(r.gaussian[0], g.gaussian), std::max(r.gaussian[1], g.gaussian)};
    r.mean = {std::min(r.mean[0], g.mean), std::max(r.mean[1], g.mean)};
  }
  if (r.gaussian[0] > r.gaussian[1]) r.gaussian = r.mean = {0, 0};
  const Tessellation& t = ev.tessellation();
  for (int fs = 0; fs < r.sides; ++fs) {
    const int ps = s.face < 0 ? fs : s.patch_side.at(fs);
    const auto curve = side_curve(scene, s, fs, ps);
    const auto& idx = t.sides[ps];
    for (std::size_t k = 0; k < idx.size(); ++k) {
      const double d = glm::length(ev.position(idx[k]) - curve(double(k) / t.density));
      r.max_boundary_deviation = std::max(r.max_boundary_deviation, std::isfinite(d) ? d : inf);
    }
  }
  return r;
}

EdgeReport analyze_shared_edge(const SceneSurfaces& ss, const SharedEdge& e) {
  const SceneSurface& a = ss.surfaces[e.surface[0]];
  const SceneSurface& b = ss.surfaces[e.surface[1]];
  EdgeReport r;
  r.edge = e.edge;
  r.faces = {a.face, b.face};
  const auto& ia = a.evaluator->tessellation().sides[e.side[0]];
  const auto& ib = b.evaluator->tessellation().sides[e.side[1]];
  // Sample k of a side of density d lies at edge parameter k / d. The two faces may have
  // different densities (the editor gives each face the density its size on screen asks for):
  // compare them at the parameters both sample, every g-th of the coarser side's samples, g the
  // greatest common divisor (all of them when the densities nest, as the editor's do).
  const long da = long(ia.size()) - 1, db = long(ib.size()) - 1;
  if (da < 1 || db < 1) return r;
  const long g = std::gcd(da, db), n = g;  // n + 1 common parameters j / n
  for (long j = 0; j <= n; ++j) {
    const std::size_t sa = ia[j * (da / g)];
    const std::size_t sb = ib[(n - j) * (db / g)];  // b runs the edge the other way
    const auto& ga = a.evaluator->geometry()[sa];
    const auto& gb = b.evaluator->geometry()[sb];
    r.max_gap =
        std::max(r.max_gap, glm::length(a.evaluator->position(sa) - b.evaluator->position(sb)));
    r.max_normal_angle_deg = std::max(r.max_normal_angle_deg, angle_deg(ga.normal, gb.normal));
    r.max_mean_curvature_jump = std::max(r.max_mean_curvature_jump, std::fabs(ga.mean - gb.mean));
  }
  return r;
}

double angle_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / M_PI;
}

SceneReport analyze_scene(const Scene& scene, const SceneSurfaces& ss, int curve_samples) {
  std::vector<CurveReport> curves;
  for (std::size_t i = 0; i < scene.curves.size(); ++i)
    curves.push_back(analyze_curve(scene.curves[i], curve_name(scene.curves[i], i), curve_samples));
  return analyze_scene(scene, ss, std::move(curves));
}

SceneReport analyze_scene(const Scene& scene, const SceneSurfaces& ss,
                          std::vector<CurveReport> curves) {
  SceneReport r;
  r.curves = std::move(curves);
  r.joints = curve_joints(scene.curves);
  for (const SceneSurface& s : ss.surfaces) r.patches.push_back(analyze_surface(scene, s));
  for (const SharedEdge& e : ss.shared_edges) r.edges.push_back(analyze_shared_edge(ss, e));
  for (const ProjectedVertex& v : ss.projected_vertices)
    r.vertices.push_back({v.vertex, v.max_angle_deg});
  return r;
}

std::string report_to_json(const SceneReport& r) {
  nlohmann::json j;
  j["patches"] = nlohmann::json::array();
  for (const PatchReport& p : r.patches) {
    j["patches"].push_back({{"name", p.name},
                            {"type", p.type},
                            {"sides", p.sides},
                            {"max_boundary_deviation", p.max_boundary_deviation},
                            {"nonfinite_samples", p.nonfinite_samples},
                            {"singular_samples", p.singular_samples},
                            {"gaussian_curvature", {p.gaussian[0], p.gaussian[1]}},
                            {"mean_curvature", {p.mean[0], p.mean[1]}}});
    if (p.degree > 0) {
      j["patches"].back()["degree"] = p.degree;
      j["patches"].back()["offsets"] = p.offsets;
    }
  }
  j["edges"] = nlohmann::json::array();
  for (const EdgeReport& e : r.edges)
    j["edges"].push_back({{"edge", e.edge},
                          {"faces", {e.faces[0], e.faces[1]}},
                          {"max_gap", e.max_gap},
                          {"max_normal_angle_deg", e.max_normal_angle_deg},
                          {"max_mean_curvature_jump", e.max_mean_curvature_jump}});
  j["vertices"] = nlohmann::json::array();
  for (const VertexReport& v : r.vertices)
    j["vertices"].push_back(
        {{"vertex", v.vertex}, {"tangent_plane_deviation_deg", v.tangent_plane_deviation_deg}});
  j["curves"] = nlohmann::json::array();
  for (const CurveReport& c : r.curves)
    j["curves"].push_back({{"name", c.name},
                           {"type", c.type},
                           {"degree", c.degree},
                           {"control_points", c.control_points},
                           {"spans", c.spans},
                           {"length", c.length},
                           {"curvature", {c.curvature[0], c.curvature[1]}},
                           {"inflections", c.inflections},
                           {"nonfinite_samples", c.nonfinite_samples}});
  j["joints"] = nlohmann::json::array();
  for (const JointReport& k : r.joints)
    j["joints"].push_back({{"curves", {k.curves[0], k.curves[1]}},
                           {"gap", k.gap},
                           {"tangent_angle_deg", k.tangent_angle_deg},
                           {"curvature_jump", k.curvature_jump}});
  return j.dump(2) + "\n";
}

std::string report_to_text(const SceneReport& r) {
  std::string out;
  char buf[512];
  for (const PatchReport& p : r.patches) {
    std::snprintf(buf, sizeof buf,
                  "patch %-12s %-14s sides %d  boundary dev %.3g  non-finite %zu  singular %zu  "
                  "K [%.6g, %.6g]  H [%.6g, %.6g]\n",
                  p.name.c_str(), p.type.c_str(), p.sides, p.max_boundary_deviation,
                  p.nonfinite_samples, p.singular_samples, p.gaussian[0], p.gaussian[1], p.mean[0],
                  p.mean[1]);
    out += buf;
    if (p.degree > 0) {
      std::snprintf(buf, sizeof buf, "  GB face: degree %d, %zu free points with offsets\n",
                    p.degree, p.offsets);
      out += buf;
    }
  }
  for (const EdgeReport& e : r.edges) {
    std::snprintf(buf, sizeof buf,
                  "edge  %-4d faces %d/%d  gap %.3g  normal angle %.3g deg  mean-curvature jump "
                  "%.3g\n",
                  e.edge, e.faces[0], e.faces[1], e.max_gap, e.max_normal_angle_deg,
                  e.max_mean_curvature_jump);
    out += buf;
  }
  for (const VertexReport& v : r.vertices) {
    std::snprintf(buf, sizeof buf, "vertex %-4d end tangents projected, up to %.3g deg\n", v.vertex,
                  v.tangent_plane_deviation_deg);
    out += buf;
  }
  for (const CurveReport& c : r.curves) {
    std::snprintf(buf, sizeof buf,
                  "curve %-12s %-13s degree %d  points %d  spans %d  length %.10g  kappa [%.6g, "
                  "%.6g]  inflections %d  non-finite %zu\n",
                  c.name.c_str(), c.type.c_str(), c.degree, c.control_points, c.spans, c.length,
                  c.curvature[0], c.curvature[1], c.inflections, c.nonfinite_samples);
    out += buf;
  }
  for (const JointReport& k : r.joints) {
    std::snprintf(buf, sizeof buf,
                  "joint curves %d/%d  gap %.3g  tangent angle %.3g deg  curvature jump %.3g\n",
                  k.curves[0], k.curves[1], k.gap, k.tangent_angle_deg, k.curvature_jump);
    out += buf;
  }
  if (out.empty()) out = "empty scene\n";
  return out;
}

}  // namespace pl
