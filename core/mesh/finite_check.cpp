#include "core/mesh/finite_check.hpp"

#include <cmath>
#include <cstdio>

#include "core/base/data_error.hpp"
#include "core/base/parallel_find.hpp"

namespace pl {

namespace {

// Samples per task of the evaluator check: a few tens of microseconds of reading.
constexpr std::size_t kCheckGrain = 16384;

// What is wrong with one sample, or nullptr.
const char* fault(const Vec3& p, const Vec3& n, double gaussian, double mean, double kmin,
                  double kmax) {
  if (!finite(p)) return "the surface point is not finite (the evaluation overflowed)";
  if (!finite(n)) return "the normal is not finite";
  // Exact normals are unit to rounding; a zero one is a singular point with no limit.
  if (!(std::fabs(glm::dot(n, n) - 1) < 1e-6))
    return "the surface is singular here and its normal has no limit (not even from inside)";
  if (!std::isfinite(gaussian) || !std::isfinite(mean) || !std::isfinite(kmin) ||
      !std::isfinite(kmax))
    return "the curvature is not finite";
  return nullptr;
}

[[noreturn]] void fail(const std::string& source, const std::string& name, Vec2 x,
                       const char* what) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "\" at (u, v) = (%.9g, %.9g)", x.x, x.y);
  throw DataError(source, "patch \"" + name + buf, what);
}

}  // namespace

void check_finite(const PatchEvaluator& ev, const std::string& name, const std::string& source) {
  const auto sample_fault = [&](std::size_t i) {
    const SurfaceGeometry& g = ev.geometry()[i];
    return fault(ev.position(i), g.normal, g.gaussian, g.mean, g.kmin, g.kmax);
  };
  // In parallel (a million samples took a fifth of their evaluation on one thread), reporting
  // the first bad sample in order, as a loop would.
  const std::size_t n = ev.sample_count();
  const std::size_t first_bad = parallel_find_first(
      n, kCheckGrain, [&](std::size_t i) { return sample_fault(i) != nullptr; });
  if (const std::size_t i = first_bad; i < n)
    fail(source, name, ev.tessellation().points[i], sample_fault(i));
}

void check_finite(std::span<const SurfaceMesh> meshes, const std::string& source) {
  for (const SurfaceMesh& m : meshes)
    for (std::size_t i = 0; i < m.positions.size(); ++i)
      if (const char* why =
              fault(m.positions[i], m.normals[i], m.gaussian[i], m.mean[i], m.kmin[i], m.kmax[i]))
        fail(source, m.name, i < m.params.size() ? m.params[i] : Vec2(NAN), why);
}

}  // namespace pl
