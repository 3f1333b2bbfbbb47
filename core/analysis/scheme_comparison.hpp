// The quality figures of every multi-sided scheme over one boundary: a network face filled by
// scheme S is the scene with that face's scheme set to S (its neighbours keep theirs), evaluated
// at one density by the incremental engine (SceneEvaluation::sync re-fills that face only). Per
// face and scheme:
//   max_normal_angle_deg      the largest angle between the face's normals and its neighbours'
//                             along every edge it shares (degrees; 0 for a G1 join)
//   max_boundary_deviation    the largest distance of the face's boundary samples from the
//                             network's edge curves evaluated on their own (model units)
//   mean, gaussian            the ranges of H and K over the samples
//   bending_energy, mean_curvature_gradient_energy, area
//                             core/analysis/surface_energy.hpp (quadrature stated there)
//   max_distance_to_base      the largest distance of the samples from the base scheme's
//                             tessellation of the same face, closest point (surface_distance.hpp:
//                             the schemes parameterize different domains, so the same parameter
//                             is not the same point and would measure the parameterizations)
//   msamples_per_s            evaluation throughput: million samples per second of the patch's
//                             jets (position, first and second derivatives, Patch::evaluate_many)
//                             and their normals and curvatures, over the face's own samples,
//                             on the calling thread, repeated for about `timing_ms`
// docs/cli.md (`compare`) lists them as the command prints them.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/scene/scene.hpp"

namespace pl {

struct SchemeFigures {
  FaceScheme scheme{};
  // Why the scheme cannot fill the face ("" when it did); the figures are then all zero.
  std::string cannot_fill;
  double max_normal_angle_deg = 0;
  double max_boundary_deviation = 0;
  std::array<double, 2> mean{0, 0}, gaussian{0, 0};
  double bending_energy = 0, mean_curvature_gradient_energy = 0, area = 0;
  double max_distance_to_base = 0;
  double msamples_per_s = 0;
};

struct FaceFigures {
  int face = -1;
  std::string name;  // the face's name, or face<i>
  int sides = 0;
  std::vector<SchemeFigures> schemes;  // in the order asked for
};

struct SchemeComparison {
  FaceScheme base{};
  int density = 0;
  std::vector<FaceFigures> faces;
};

struct ComparisonOptions {
  std::vector<int> faces;           // network faces; empty: every face
  std::vector<FaceScheme> schemes;  // empty: comparable_schemes()
  FaceScheme base = FaceScheme::GB;
  int density = 32;
  double timing_ms = 20;  // per face and scheme; 0: throughput not measured (left 0)
  // Asked between two fillings; true stops the comparison (it then throws Cancelled).
  std::function<bool()> cancelled;
};

struct ComparisonCancelled : std::runtime_error {
  ComparisonCancelled() : std::runtime_error("comparison cancelled") {}
};

// Throws DataError(source, ...) for a scene without network faces, a face index out of range,
// a base scheme that cannot fill one of the faces (naming it), or non-finite samples.
SchemeComparison compare_schemes(const Scene& scene, const ComparisonOptions& options,
                                 const std::string& source);

// The `compare --json` object and the table of the text output (docs/cli.md).
std::string comparison_to_json(const SchemeComparison& comparison);
std::string comparison_to_text(const SchemeComparison& comparison);

}  // namespace pl
