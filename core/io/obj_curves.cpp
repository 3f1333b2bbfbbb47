#include "core/io/obj_curves.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/base/data_error.hpp"
#include "core/io/input_limits.hpp"

namespace pl {

namespace {

// One number of a `v` line, or an error naming the line.
double coordinate(const std::string& token, const std::string& file, const std::string& where) {
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(x))
    throw DataError(file, where, "\"" + token + "\" is not a number");
  if (std::fabs(x) > kMaxCoordinate)
    throw DataError(file, where, "coordinate " + token + " is beyond the input limit");
  return x;
}

// The vertex index of an `l` token ("7", "-2", "7/3"), 0-based.
std::size_t vertex_index(const std::string& token, std::size_t vertices, const std::string& file,
                         const std::string& where) {
  const std::string head = token.substr(0, token.find('/'));
  char* end = nullptr;
  const long i = std::strtol(head.c_str(), &end, 10);
  if (head.empty() || end != head.c_str() + head.size() || i == 0)
    throw DataError(file, where, "\"" + token + "\" is not a vertex index");
  const long k = i > 0 ? i - 1 : static_cast<long>(vertices) + i;
  if (k < 0 || k >= static_cast<long>(vertices))
    throw DataError(
        file, where,
        "vertex " + head + " does not exist (" + std::to_string(vertices) + " vertices so far)");
  return static_cast<std::size_t>(k);
}

}  // namespace

ObjCurves read_obj_curves(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw DataError(file, "", "no such file");
  if (std::filesystem::file_size(path, ec) > kMaxInputBytes)
    throw DataError(file, "", "larger than the input limit");
  std::ifstream in(path);
  if (!in) throw DataError(file, "", "cannot be read");
  std::vector<Vec3> vertices;
  ObjCurves out;
  std::string line, name = path.stem().string();
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = "line " + std::to_string(number);
    std::istringstream words(line);
    std::string kind;
    if (!(words >> kind) || kind[0] == '#') continue;
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    if (kind == "v") {
      if (args.size() < 3 || args.size() > 4)
        throw DataError(file, where, "a vertex has three coordinates (and an optional weight)");
      vertices.emplace_back(coordinate(args[0], file, where), coordinate(args[1], file, where),
                            coordinate(args[2], file, where));
    } else if ((kind == "o" || kind == "g") && !args.empty()) {
      name = args[0];
    } else if (kind == "f") {
      ++out.faces_passed_over;
    } else if (kind == "l") {
      if (args.size() < 2) throw DataError(file, where, "a line needs two points at least");
      SceneCurve c;
      c.type = CurveType::BSpline;
      c.degree = 1;
      c.name = name + " line " + std::to_string(number);
      for (const std::string& a : args) {
        const Vec3 p = vertices[vertex_index(a, vertices.size(), file, where)];
        if (!c.points.empty() && p == c.points.back())
          throw DataError(file, where, "the line repeats a point (" + a + "): no segment there");
        c.points.push_back(p);
      }
      const int m = static_cast<int>(c.points.size());
      c.knots.push_back(0);
      for (int k = 0; k < m; ++k) c.knots.push_back(k);
      c.knots.push_back(m - 1);
      out.curves.push_back(std::move(c));
    }
  }
  if (in.bad()) throw DataError(file, "", "cannot be read");
  if (out.curves.empty())
    throw DataError(file, "",
                    "no polyline (`l` line) in the file" +
                        (out.faces_passed_over
                             ? " (faces are not curves: " + std::to_string(out.faces_passed_over) +
                                   " passed over)"
                             : std::string()));
  return out;
}

}  // namespace pl
