// PatchSamples.evaluate_at: the patch at domain points given from Python. The output arrays are
// allocated uninitialised and filled in parallel (oneTBB) by the patch's batched evaluation and
// the batched differential geometry, the loops of PatchEvaluator::evaluate_all; the returned
// arrays are views of those two buffers.
#include <cmath>

#include "app/python/bindings.hpp"
#include "core/base/parallel_find.hpp"

namespace pl::python {

namespace {

// Whether x lies in the polygon of the domain's corners (counter-clockwise, straight sides), on
// its boundary included, up to `tol`: the winding number first (no square roots: most points are
// inside), the distance to the sides only for a point it finds outside.
bool in_domain(const std::vector<Vec2>& corners, const Vec2& x, double tol) {
  int winding = 0;
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % n];
    const double side = (b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x);
    if (a.y <= x.y) {
      if (b.y > x.y && side > 0) ++winding;
    } else if (b.y <= x.y && side < 0) {
      --winding;
    }
  }
  if (winding != 0) return true;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = corners[i], ab = corners[(i + 1) % n] - a, ax = x - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(glm::dot(ax, ab) / len2, 0.0, 1.0) : 0.0;
    if (glm::length(ax - t * ab) <= tol) return true;
  }
  return false;
}

constexpr std::size_t kChunk = 512;  // samples per evaluate_many call, as in evaluate_all

}  // namespace

namespace {

// The writable, C-contiguous buffer of `dtype` and shape (n, columns) under the arrays of an
// earlier evaluate_at result (`out[key].base`); ValueError for anything else.
py::array out_buffer(const py::dict& out, const char* key, const py::dtype& dtype, std::size_t n,
                     std::size_t columns) {
  const auto bad = [&] {
    return py::value_error(
        "out takes a dict returned by evaluate_at for the same number of points");
  };
  if (!out.contains(key)) throw bad();
  const py::object view = out[key];
  if (!py::isinstance<py::array>(view)) throw bad();
  const py::object base = view.attr("base");
  if (!py::isinstance<py::array>(base)) throw bad();
  const auto a = py::reinterpret_borrow<py::array>(base);
  if (!a.dtype().is(dtype) || a.ndim() != 2 || std::size_t(a.shape(0)) != n ||
      std::size_t(a.shape(1)) != columns || !(a.flags() & py::array::c_style) || !a.writeable() ||
      !a.owndata())
    throw bad();
  return a;
}

}  // namespace

py::dict evaluate_points(const PySamples& s,
                         const py::array_t<double, py::array::c_style | py::array::forcecast>& uv,
                         const std::optional<py::dict>& out) {
  if (uv.ndim() != 2 || uv.shape(1) != 2)
    throw py::value_error("evaluate_at takes an N x 2 array of domain points (u, v)");
  const std::size_t n = static_cast<std::size_t>(uv.shape(0));
  static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(SurfaceJet) == 18 * sizeof(double));
  const std::span<const Vec2> xs(reinterpret_cast<const Vec2*>(uv.data()), n);
  const Patch& patch = s.evaluator->patch();
  const Domain& domain = patch.domain();
  std::vector<Vec2> corners;
  double extent = 0;
  for (int i = 0; i < domain.side_count(); ++i) {
    corners.push_back(domain.side_point(i, 0));
    extent = std::max(extent, glm::length(corners.back() - corners.front()));
  }
  // The first point outside the domain (or not finite), found in parallel.
  const double tol = 1e-12 * std::max(extent, 1.0);
  std::size_t first_bad = n;
  {
    py::gil_scoped_release release;
    first_bad = parallel_find_first(n, 8192, [&](std::size_t i) {
      return !std::isfinite(xs[i].x) || !std::isfinite(xs[i].y) || !in_domain(corners, xs[i], tol);
    });
  }
  if (const std::size_t i = first_bad; i < n)
    throw py::value_error("domain point " + std::to_string(i) + " (" + std::to_string(xs[i].x) +
                          ", " + std::to_string(xs[i].y) + ") is not in the patch's domain");
  // New arrays, or the buffers of an earlier result (filled again: no allocation, no page faults).
  py::array jets = out ? out_buffer(*out, "positions", py::dtype::of<double>(), n, 18)
                       : py::array_t<double>({py::ssize_t(n), py::ssize_t(18)});
  py::array geometry =
      out ? out_buffer(*out, "normals", py::dtype::of<uint8_t>(), n, sizeof(SurfaceGeometry))
          : py::array_t<uint8_t>({py::ssize_t(n), py::ssize_t(sizeof(SurfaceGeometry))});
  const std::span<SurfaceJet> jet(static_cast<SurfaceJet*>(jets.mutable_data()), n);
  const std::span<SurfaceGeometry> geo(static_cast<SurfaceGeometry*>(geometry.mutable_data()), n);
  {
    py::gil_scoped_release release;
    parallel_chunks(n, s.evaluator->grains().evaluate, [&](std::size_t first, std::size_t last) {
      for (std::size_t b = first; b < last; b += kChunk) {
        const std::size_t e = std::min(last, b + kChunk);
        patch.evaluate_many(xs.subspan(b, e - b), jet.subspan(b, e - b));
        differential_geometry_many(jet.subspan(b, e - b), geo.subspan(b, e - b));
      }
    });
  }
  // Views: columns of the jets, and the fields of the geometry records.
  const auto jet_columns = [&](int first) {
    return py::array(py::dtype::of<double>(), {py::ssize_t(n), py::ssize_t(3)},
                     {py::ssize_t(sizeof(SurfaceJet)), py::ssize_t(sizeof(double))},
                     static_cast<const double*>(jets.data()) + first, jets);
  };
  const SurfaceGeometry* g = geo.data();
  const auto field = [&](const void* first, py::dtype type, std::vector<py::ssize_t> shape,
                         std::vector<py::ssize_t> strides) {
    return py::array(type, std::move(shape), std::move(strides), first, geometry);
  };
  const py::ssize_t rec = sizeof(SurfaceGeometry), N = static_cast<py::ssize_t>(n);
  static const SurfaceGeometry none{};
  const SurfaceGeometry* g0 = n ? g : &none;
  if (out) return *out;  // its views see the buffers just filled
  py::dict result;
  result["positions"] = jet_columns(0);
  result["su"] = jet_columns(3);
  result["sv"] = jet_columns(6);
  result["suu"] = jet_columns(9);
  result["suv"] = jet_columns(12);
  result["svv"] = jet_columns(15);
  result["normals"] = field(&g0->normal.x, py::dtype::of<double>(), {N, 3}, {rec, 8});
  result["mean_curvature"] = field(&g0->mean, py::dtype::of<double>(), {N}, {rec});
  result["gaussian_curvature"] = field(&g0->gaussian, py::dtype::of<double>(), {N}, {rec});
  result["k_min"] = field(&g0->kmin, py::dtype::of<double>(), {N}, {rec});
  result["k_max"] = field(&g0->kmax, py::dtype::of<double>(), {N}, {rec});
  static_assert(sizeof(GeometryStatus) == 1 && uint8_t(GeometryStatus::Regular) == 0);
  result["singular"] = field(&g0->status, py::dtype::of<bool>(), {N}, {rec});
  return result;
}

}  // namespace pl::python
