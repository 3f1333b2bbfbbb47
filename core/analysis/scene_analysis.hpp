// Surface-quality figures of the CLI spec's `analyze`: boundary interpolation, finiteness,
// curvature ranges per patch; gap, normal angle and mean-curvature jump per shared edge.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/analysis/curve_analysis.hpp"
#include "core/eval/scene_surfaces.hpp"

namespace pl {

struct PatchReport {
  std::string name, type;
  int sides = 0;
  double max_boundary_deviation = 0;
  std::size_t nonfinite_samples = 0;
  std::size_t singular_samples = 0;  // where Su x Sv vanishes (normal from the limit)
  std::array<double, 2> gaussian{0, 0}, mean{0, 0};
  // GB network faces (interior control, docs/scene-format.md): the degree and how many free
  // points carry offsets; degree 0 for every other surface.
  int degree = 0;
  std::size_t offsets = 0;
};

struct EdgeReport {
  int edge = -1;
  std::array<int, 2> faces{-1, -1};
  double max_gap = 0, max_normal_angle_deg = 0, max_mean_curvature_jump = 0;
};

struct VertexReport {
  int vertex = -1;
  double tangent_plane_deviation_deg = 0;
};

struct SceneReport {
  std::vector<PatchReport> patches;
  std::vector<EdgeReport> edges;
  std::vector<VertexReport> vertices;
  std::vector<CurveReport> curves;  // free curves (core/analysis/curve_analysis.hpp)
  std::vector<JointReport> joints;
};

// curve_samples: samples per span of each free curve (the CLI's --density).
SceneReport analyze_scene(const Scene& scene, const SceneSurfaces& surfaces,
                          int curve_samples = 32);
// The same with the reports of the scene's curves already made (checked_curve_report), one per
// curve in order.
SceneReport analyze_scene(const Scene& scene, const SceneSurfaces& surfaces,
                          std::vector<CurveReport> curves);

// The figures of one surface, and of one edge two faces share (what analyze_scene lists).
PatchReport analyze_surface(const Scene& scene, const SceneSurface& surface);
EdgeReport analyze_shared_edge(const SceneSurfaces& surfaces, const SharedEdge& edge);

// Angle between two unit vectors in degrees, accurate for tiny angles (atan2 form).
double angle_deg(const Vec3& a, const Vec3& b);

std::string report_to_json(const SceneReport& report);
std::string report_to_text(const SceneReport& report);

}  // namespace pl
