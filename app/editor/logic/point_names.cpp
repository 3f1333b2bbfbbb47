#include "app/editor/logic/point_names.hpp"

#include <sstream>

namespace pl {

std::optional<PointRef> parse_point_name(const std::string& name) {
  std::istringstream in(name);
  std::string word, second;
  int a = -1, b = -1;
  if (!(in >> word >> a) || a < 0) return std::nullopt;
  std::optional<PointRef> r;
  if (word == "vertex") {
    r = PointRef::vertex(a);
  } else if (word == "edge" && in >> second >> b && second == "handle" && (b == 0 || b == 1)) {
    r = PointRef::handle(a, b);
  } else if (word == "patch" && in >> second >> b && second == "point" && b >= 0) {
    r = PointRef::patch_point(a, b);
  } else if (word == "curve" && in >> second >> b && second == "point" && b >= 0) {
    r = PointRef::curve_point(a, b);
  }
  std::string rest;
  if (in >> rest) return std::nullopt;  // trailing words
  return r;
}

}  // namespace pl
