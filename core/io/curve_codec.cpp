#include "core/io/curve_codec.hpp"

#include <cmath>
#include <stdexcept>

#include "core/io/input_limits.hpp"
#include "core/io/patch_codec.hpp"
#include "core/math/bspline_basis.hpp"

namespace pl {

namespace {

CurveType read_type(const JsonNode& node) {
  const std::string t = node.string();
  for (CurveType c : {CurveType::Bezier, CurveType::Interpolating, CurveType::Hermite,
                      CurveType::BSpline, CurveType::Nurbs})
    if (t == curve_type_name(c)) return c;
  node.fail("unknown curve type \"" + printable(t) +
            "\" (known: bezier, interpolating, hermite, bspline, nurbs)");
}

// `packed`: the points already read by the parser (json_node.hpp), `node` then holding null.
std::vector<Vec3> read_points(const JsonNode& node, std::size_t at_least, std::size_t at_most,
                              std::vector<Vec3>* packed) {
  const std::size_t n = packed ? packed->size() : node.size();
  if (n < at_least || n > at_most)
    node.fail(at_least == at_most
                  ? "expected " + std::to_string(at_least) + " points, got " + std::to_string(n)
                  : "expected " + std::to_string(at_least) + " to " + std::to_string(at_most) +
                        " points, got " + std::to_string(n));
  return packed ? std::move(*packed) : node.points();
}

// The knots under "knots" checked one by one so the message names the offending entry.
std::vector<double> read_curve_knots(const JsonNode& node, int p, std::size_t n) {
  const auto items = node.items(n + p + 1);
  std::vector<double> U;
  for (std::size_t i = 0; i < items.size(); ++i) {
    U.push_back(items[i].number());
    if (std::abs(U[i]) > kMaxCoordinate)
      items[i].fail("knot " + short_number(U[i]) + " is out of range: |t| <= " +
                    short_number(kMaxCoordinate) + " keeps knot differences finite");
    if (i > 0 && U[i] < U[i - 1])
      items[i].fail("knots must not decrease (" + short_number(U[i]) + " after " +
                    short_number(U[i - 1]) + ")");
    if (i > std::size_t(p) && U[i] == U[i - p - 1])
      items[i].fail("knot " + short_number(U[i]) +
                    " has multiplicity above degree + 1 = " + std::to_string(p + 1));
  }
  if (!(U[p] < U[n]))
    node.fail("empty parameter range: knots[" + std::to_string(p) + "] = knots[" +
              std::to_string(n) + "] = " + short_number(U[p]));
  return U;
}

void read_spline_keys(const JsonNode& node, SceneCurve& c, std::vector<Vec3>* packed) {
  c.degree = node.at("degree").integer_in(1, kMaxSplineDegree);
  const JsonNode pts = node.at("points");
  c.points = read_points(pts, c.degree + 1, 1000000, packed);
  if (auto k = node.find("knots")) {
    c.knots = read_curve_knots(*k, c.degree, c.points.size());
  } else {
    // Clamped uniform on [0, 1].
    const std::size_t n = c.points.size(), spans = n - c.degree;
    for (std::size_t i = 0; i < n + c.degree + 1; ++i) {
      const long k = static_cast<long>(i) - c.degree;
      c.knots.push_back(k <= 0 ? 0.0 : k >= long(spans) ? 1.0 : double(k) / double(spans));
    }
  }
}

}  // namespace

SceneCurve read_curve(const JsonNode& node, std::vector<Vec3>* packed_points) {
  node.require_object();
  SceneCurve c;
  c.type = read_type(node.at("type"));
  if (auto name = node.find("name")) c.name = name->string();
  switch (c.type) {
    case CurveType::Bezier:
      node.allow_only({"type", "name", "points"});
      c.points = read_points(node.at("points"), 2, kMaxSplineDegree + 1, packed_points);
      break;
    case CurveType::Interpolating:
      node.allow_only({"type", "name", "points"});
      c.points = read_points(node.at("points"), 4, 4, packed_points);
      break;
    case CurveType::Hermite: {
      node.allow_only({"type", "name", "points", "tangents"});
      c.points = read_points(node.at("points"), 2, 2, packed_points);
      const JsonNode t = node.at("tangents");
      t.items(2);
      c.tangents = t.points();
      break;
    }
    case CurveType::BSpline:
      node.allow_only({"type", "name", "degree", "points", "knots"});
      read_spline_keys(node, c, packed_points);
      break;
    case CurveType::Nurbs: {
      node.allow_only({"type", "name", "degree", "points", "knots", "weights"});
      read_spline_keys(node, c, packed_points);
      const auto w = node.at("weights").items(c.points.size());
      for (const JsonNode& x : w) {
        c.weights.push_back(x.number());
        if (!(c.weights.back() > 0))
          x.fail("a weight must be positive, got " + short_number(c.weights.back()));
      }
      break;
    }
  }
  try {
    validate_curve(c);  // the checks above name the entry; this one guards the whole
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
  return c;
}

std::vector<CurveKey> curve_keys(const SceneCurve& c) {
  const bool spline = c.type == CurveType::BSpline || c.type == CurveType::Nurbs;
  std::vector<CurveKey> keys;
  keys.push_back({"type", std::string(curve_type_name(c.type))});
  if (!c.name.empty()) keys.push_back({"name", c.name});
  if (spline) keys.push_back({"degree", c.degree});
  keys.push_back({"points", nullptr, &c.points});
  if (c.type == CurveType::Hermite) keys.push_back({"tangents", nullptr, &c.tangents});
  if (spline) keys.push_back({"knots", nullptr, nullptr, &c.knots});
  if (c.type == CurveType::Nurbs) keys.push_back({"weights", nullptr, nullptr, &c.weights});
  return keys;
}

nlohmann::json curve_json(const SceneCurve& c) {
  nlohmann::json j;
  for (CurveKey& k : curve_keys(c)) {
    if (k.points)
      j[k.key] = points_json(*k.points);
    else if (k.numbers)
      j[k.key] = *k.numbers;
    else
      j[k.key] = std::move(k.value);
  }
  return j;
}

}  // namespace pl
