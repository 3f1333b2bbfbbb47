// Arguments from Python checked as the CLI checks its own (the same bounds, ValueError for the
// rest), so nothing out of range reaches the core.
#include <cmath>
#include <string>

#include "app/cli/load_input.hpp"
#include "app/python/bindings.hpp"
#include "core/io/input_limits.hpp"

namespace pl::python {

Vec3 to_point(const py::handle& p, const char* what) {
  const auto bad = [&] {
    return py::value_error(std::string(what) + " takes three finite numbers, each within ±" +
                           std::to_string(kMaxCoordinate));
  };
  if (!py::isinstance<py::sequence>(p) || py::isinstance<py::str>(p)) throw bad();
  const auto s = py::reinterpret_borrow<py::sequence>(p);
  if (s.size() != 3) throw bad();
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const double c = py::cast<double>(s[i]);
    if (!std::isfinite(c) || std::abs(c) > kMaxCoordinate) throw bad();
    v[i] = c;
  }
  return v;
}

std::optional<FaceScheme> to_scheme(const std::optional<std::string>& scheme) {
  return parse_scheme_option(scheme);  // the CLI's --scheme: UsageError, a ValueError here
}

int checked_density(int density) {
  if (density < 1 || density > kMaxDensity)
    throw py::value_error("density takes 1 to " + std::to_string(kMaxDensity) + ", got " +
                          std::to_string(density));
  return density;
}

}  // namespace pl::python
