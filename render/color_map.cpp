#include "render/color_map.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

// Stops chosen for a perceptually even walk from saturated blue through near-white to
// saturated red; the neutral centre is slightly warm grey so it still reads as a colour on white.
constexpr std::array<Rgb, 5> kStops{{
    {0.110f, 0.240f, 0.600f},
    {0.400f, 0.620f, 0.880f},
    {0.955f, 0.950f, 0.940f},
    {0.940f, 0.560f, 0.390f},
    {0.650f, 0.070f, 0.130f},
}};

}  // namespace

Rgb color_map(double t) {
  if (!(t >= 0)) t = 0;  // also NaN
  if (t > 1) t = 1;
  const double x = t * (kStops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kStops.size() - 2);
  const float f = static_cast<float>(x - static_cast<double>(i));
  Rgb c;
  for (int k = 0; k < 3; ++k) c[k] = kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k]);
  return c;
}

const char* curvature_name(CurvatureKind kind) {
  switch (kind) {
    case CurvatureKind::Gaussian:
      return "gaussian";
    case CurvatureKind::Mean:
      return "mean";
    case CurvatureKind::Kmin:
      return "kmin";
    case CurvatureKind::Kmax:
      return "kmax";
  }
  return "";
}

const std::vector<double>& curvature_values(const SurfaceMesh& mesh, CurvatureKind kind) {
  switch (kind) {
    case CurvatureKind::Gaussian:
      return mesh.gaussian;
    case CurvatureKind::Mean:
      return mesh.mean;
    case CurvatureKind::Kmin:
      return mesh.kmin;
    case CurvatureKind::Kmax:
      return mesh.kmax;
  }
  return mesh.mean;
}

double ColorRange::normalized(double value) const {
  if (std::isnan(value)) return 0.5;  // no information: the neutral colour, not an extreme
  const double t = value < 0 ? 0.5 - 0.5 * value / lo : 0.5 + 0.5 * value / hi;
  return std::clamp(t, 0.0, 1.0);
}

ColorRange automatic_range(std::span<const SurfaceMesh* const> meshes, CurvatureKind kind,
                           double percentile) {
  std::vector<double> magnitudes;
  for (const SurfaceMesh* m : meshes)
    for (double v : curvature_values(*m, kind))
      if (std::isfinite(v)) magnitudes.push_back(std::abs(v));
  double r = 0;
  if (!magnitudes.empty()) {
    const double q = std::clamp(percentile, 0.0, 100.0) / 100.0;
    const auto k = static_cast<std::size_t>(std::lround(q * (magnitudes.size() - 1)));
    std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
    r = magnitudes[k];
    // A field that is zero almost everywhere still shows its few non-zero samples.
    if (r == 0) r = *std::max_element(magnitudes.begin(), magnitudes.end());
  }
  // A flat surface: any symmetric range shows the neutral colour; 1 gives a readable legend.
  if (!(r > 0)) r = 1;
  return {-r, r};
}

std::vector<float> color_map_table(int entries) {
  std::vector<float> out;
  out.reserve(static_cast<std::size_t>(entries) * 3);
  for (int i = 0; i < entries; ++i) {
    const Rgb c = color_map(static_cast<double>(i) / (entries - 1));
    out.insert(out.end(), c.begin(), c.end());
  }
  return out;
}

}  // namespace pl
