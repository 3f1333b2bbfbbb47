#include "core/analysis/scheme_comparison.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/analysis/compared_schemes.hpp"
#include "core/analysis/scene_analysis.hpp"
#include "core/analysis/surface_distance.hpp"
#include "core/analysis/surface_energy.hpp"
#include "core/base/data_error.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/scene/network_edit.hpp"
#include "core/scene/surface_names.hpp"

namespace pl {

namespace {

int surface_of_face(const SceneSurfaces& ss, int face) {
  for (std::size_t i = 0; i < ss.surfaces.size(); ++i)
    if (ss.surfaces[i].face == face) return int(i);
  return -1;
}

// A sample's figures must be numbers: the comparison prints nothing it cannot stand behind.
void check_finite_samples(const PatchEvaluator& ev, const std::string& name,
                          const std::string& source) {
  for (std::size_t i = 0; i < ev.sample_count(); ++i)
    if (!ev.finite(i)) {
      const Vec2 x = ev.tessellation().points[i];
      char where[160];
      std::snprintf(where, sizeof where, "face \"%s\" at (u, v) = (%.17g, %.17g)", name.c_str(),
                    x.x, x.y);
      throw DataError(source, where, "the surface is not finite there");
    }
}

struct Samples {
  std::vector<Vec3> positions, normals;
};
Samples samples_of(const PatchEvaluator& ev) {
  Samples s;
  s.positions.resize(ev.sample_count());
  s.normals.resize(ev.sample_count());
  for (std::size_t i = 0; i < ev.sample_count(); ++i) {
    s.positions[i] = ev.position(i);
    s.normals[i] = ev.geometry()[i].normal;
  }
  return s;
}

double throughput_msamples_per_s(const PatchEvaluator& ev, double timing_ms) {
  if (timing_ms <= 0) return 0;
  const auto& xs = ev.tessellation().points;
  std::vector<SurfaceJet> jets(xs.size());
  std::vector<SurfaceGeometry> geometry(xs.size());
  using clock = std::chrono::steady_clock;
  const SharedBasisBypass alone;  // the face on its own, not a basis kept from its last round
  const auto t0 = clock::now();
  std::size_t samples = 0;
  double ms = 0;
  do {
    ev.patch().evaluate_many(xs, jets);
    differential_geometry_many(jets, geometry);
    samples += xs.size();
    ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  } while (ms < timing_ms);
  return ms > 0 ? double(samples) / (ms * 1e3) : 0;
}

SchemeFigures figures_of(const Scene& scene, const SceneSurfaces& ss, int index,
                         const TriangleSurface& base, const ComparisonOptions& o) {
  const SceneSurface& s = ss.surfaces[index];
  const PatchEvaluator& ev = *s.evaluator;
  SchemeFigures f;
  const PatchReport report = analyze_surface(scene, s);
  f.max_boundary_deviation = report.max_boundary_deviation;
  f.mean = report.mean;
  f.gaussian = report.gaussian;
  for (const SharedEdge& e : ss.shared_edges)
    if (e.surface[0] == index || e.surface[1] == index)
      f.max_normal_angle_deg =
          std::max(f.max_normal_angle_deg, analyze_shared_edge(ss, e).max_normal_angle_deg);
  const SurfaceIntegrals integrals = surface_integrals(ev);
  f.area = integrals.area;
  f.bending_energy = integrals.bending_energy;
  f.mean_curvature_gradient_energy = integrals.mean_curvature_gradient_energy;
  const Samples samples = samples_of(ev);
  for (double d : signed_distance_to(samples.positions, base))
    f.max_distance_to_base = std::max(f.max_distance_to_base, std::fabs(d));
  f.msamples_per_s = throughput_msamples_per_s(ev, o.timing_ms);
  return f;
}

}  // namespace

SchemeComparison compare_schemes(const Scene& scene, const ComparisonOptions& o,
                                 const std::string& source) {
  if (!scene.network || scene.network->faces.empty())
    throw DataError(source, "network", "the scene has no network faces to compare");
  const int face_count = int(scene.network->faces.size());
  std::vector<int> faces = o.faces;
  if (faces.empty())
    for (int f = 0; f < face_count; ++f) faces.push_back(f);
  for (int f : faces)
    if (f < 0 || f >= face_count)
      throw DataError(
          source, "network.faces",
          "no face " + std::to_string(f) + " (the network has " + std::to_string(face_count) + ")");
  const std::vector<FaceScheme> schemes = o.schemes.empty() ? comparable_schemes() : o.schemes;

  SchemeComparison out;
  out.base = o.base;
  out.density = o.density;
  // One evaluation follows every filling: each is one face's scheme changed, which the engine
  // re-fills and re-evaluates alone. Compact samples: nothing here moves a point.
  SceneEvaluation evaluation(scene, o.density, std::nullopt, source, SampleStorage::Compact);
  Scene work = scene;
  Network& net = *work.network;
  for (int face : faces) {
    FaceFigures ff;
    ff.face = face;
    ff.name = face_surface_name(net, face);
    ff.sides = int(net.faces[face].loop.size());
    const FaceScheme own = net.faces[face].scheme;
    // Fills the face with `scheme`; returns why it cannot be, or "".
    auto fill = [&](FaceScheme scheme) -> std::string {
      if (o.cancelled && o.cancelled()) throw ComparisonCancelled();
      try {
        set_face_scheme(net, face, scheme);
        evaluation.sync(work);
      } catch (const EditRefused& e) {
        return e.what();
      } catch (const DataError& e) {
        net.faces[face].scheme = own;  // the evaluation kept the last filling
        return e.message();
      }
      return {};
    };
    const std::string where = "network.faces[" + std::to_string(face) + "]";
    if (const std::string why = fill(o.base); !why.empty())
      throw DataError(source, where,
                      "the base scheme " + scheme_keyword(o.base) + " cannot fill face \"" +
                          ff.name + "\": " + why);
    const int base_index = surface_of_face(evaluation.surfaces(), face);
    const PatchEvaluator& base_ev = *evaluation.surfaces().surfaces.at(base_index).evaluator;
    check_finite_samples(base_ev, ff.name, source);
    // Kept: the evaluator is replaced when the next scheme fills the face.
    const Samples base_samples = samples_of(base_ev);
    const auto base_triangles = base_ev.tessellation().triangles;
    const TriangleSurface base{base_samples.positions, base_samples.normals, base_triangles};
    for (FaceScheme scheme : schemes) {
      SchemeFigures f;
      if (std::string why = fill(scheme); !why.empty()) {
        f.cannot_fill = std::move(why);
      } else {
        const int index = surface_of_face(evaluation.surfaces(), face);
        check_finite_samples(*evaluation.surfaces().surfaces.at(index).evaluator, ff.name, source);
        f = figures_of(work, evaluation.surfaces(), index, base, o);
      }
      f.scheme = scheme;
      ff.schemes.push_back(std::move(f));
    }
    net.faces[face].scheme = own;
    out.faces.push_back(std::move(ff));
  }
  return out;
}

std::string comparison_to_json(const SchemeComparison& c) {
  // Keys in the documented order (docs/cli.md), schemes in the order asked for.
  using Json = nlohmann::ordered_json;
  Json j;
  j["base"] = scheme_keyword(c.base);
  j["faces"] = Json::array();
  for (const FaceFigures& ff : c.faces) {
    Json schemes = Json::object();
    for (const SchemeFigures& f : ff.schemes) {
      if (!f.cannot_fill.empty()) {
        schemes[scheme_keyword(f.scheme)] = {{"cannot_fill", f.cannot_fill}};
        continue;
      }
      schemes[scheme_keyword(f.scheme)] = {
          {"max_normal_angle_deg", f.max_normal_angle_deg},
          {"max_boundary_deviation", f.max_boundary_deviation},
          {"mean_curvature", {f.mean[0], f.mean[1]}},
          {"gaussian_curvature", {f.gaussian[0], f.gaussian[1]}},
          {"bending_energy", f.bending_energy},
          {"mean_curvature_gradient_energy", f.mean_curvature_gradient_energy},
          {"area", f.area},
          {"max_distance_to_base", f.max_distance_to_base},
          {"msamples_per_s", f.msamples_per_s}};
    }
    j["faces"].push_back({{"face", ff.name}, {"sides", ff.sides}, {"schemes", schemes}});
  }
  return j.dump(2) + "\n";
}

std::string comparison_to_text(const SchemeComparison& c) {
  std::string out;
  char buf[512];
  for (const FaceFigures& ff : c.faces) {
    std::snprintf(buf, sizeof buf, "face %s (%d sides), density %d, distances to %s\n",
                  ff.name.c_str(), ff.sides, c.density, scheme_keyword(c.base).c_str());
    out += buf;
    std::snprintf(buf, sizeof buf, "  %-18s %10s %10s %23s %23s %10s %10s %10s %10s %8s\n",
                  "scheme", "G1 deg", "bound dev", "H range", "K range", "bending", "grad H",
                  "area", "to base", "Msmp/s");
    out += buf;
    for (const SchemeFigures& f : ff.schemes) {
      if (!f.cannot_fill.empty()) {
        std::snprintf(buf, sizeof buf, "  %-18s cannot fill this face: %s\n",
                      scheme_keyword(f.scheme).c_str(), f.cannot_fill.c_str());
        out += buf;
        continue;
      }
      std::snprintf(buf, sizeof buf,
                    "  %-18s %10.3g %10.3g [%10.4g,%10.4g] [%10.4g,%10.4g] %10.4g %10.4g %10.5g "
                    "%10.3g %8.3g\n",
                    scheme_keyword(f.scheme).c_str(), f.max_normal_angle_deg,
                    f.max_boundary_deviation, f.mean[0], f.mean[1], f.gaussian[0], f.gaussian[1],
                    f.bending_energy, f.mean_curvature_gradient_energy, f.area,
                    f.max_distance_to_base, f.msamples_per_s);
      out += buf;
    }
  }
  return out;
}

}  // namespace pl
