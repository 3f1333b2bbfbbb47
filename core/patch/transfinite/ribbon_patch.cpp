#include "core/patch/transfinite/ribbon_patch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/patch/transfinite/angular_domain.hpp"
#include "core/patch/transfinite/vec_jet.hpp"

namespace pl {

using transfinite::RibbonCurves;
using transfinite::RibbonScheme;
using transfinite::RibbonSet;
using transfinite::SchemeInput;
using transfinite::UnitCurve;

namespace {

std::string str(int i) {
  return std::to_string(i);
}
std::string vec_str(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
  return buf;
}

UnitCurve unit_curve(const SceneCurve& c, int side, const char* which) {
  if (c.type != CurveType::Bezier && c.type != CurveType::BSpline && c.type != CurveType::Nurbs)
    throw std::invalid_argument("side " + str(side) + ": the " + which +
                                " must be a bezier, bspline or nurbs curve, not " +
                                std::string(curve_type_name(c.type)));
  try {
    validate_curve(c);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("side " + str(side) + ", " + which + ": " + e.what());
  }
  SplineCurve s = spline_form(c);
  if (s.points.size() != c.points.size())
    throw std::invalid_argument("side " + str(side) + ": the " + which +
                                " has no control-point form");  // not reached for these types
  return UnitCurve(std::move(s));
}

std::vector<RibbonCurves> unit_sides(const std::vector<RibbonSide>& sides) {
  std::vector<RibbonCurves> out;
  for (std::size_t i = 0; i < sides.size(); ++i)
    out.push_back({unit_curve(sides[i].curve, int(i), "curve"),
                   unit_curve(sides[i].cross, int(i), "cross derivative")});
  return out;
}

double curves_diagonal(const std::vector<RibbonSide>& sides) {
  Vec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const RibbonSide& s : sides)
    for (const Vec3& p : s.curve.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

Jet component(const SurfaceJet& s, int c) {
  return {s.p[c], s.su[c], s.sv[c], s.suu[c], s.suv[c], s.svv[c]};
}

}  // namespace

std::string ribbon_corner_problem(const std::vector<RibbonSide>& sides, int corner) {
  const int n = static_cast<int>(sides.size());
  const std::vector<RibbonCurves> u = unit_sides(sides);
  const int i = corner, k = (corner + 1) % n;
  const RibbonCurves& a = u[i];
  const RibbonCurves& b = u[k];
  const std::string where =
      "corner " + str(i) + " (end of side " + str(i) + ", start of side " + str(k) + "): ";
  const double gap = glm::length(a.curve.at(1).p - b.curve.at(0).p);
  const double scale = curves_diagonal(sides);
  if (!(gap <= kCornerGap * scale))
    return where + "the curves do not meet (gap " + std::to_string(gap) + ", allowed " +
           std::to_string(kCornerGap * scale) + ": 1e-9 of the boundary's size)";
  const auto mismatch = [](const Vec3& x, const Vec3& y) {
    const double len = std::max(glm::length(x), glm::length(y));
    return !(glm::length(x - y) <= kCornerTangent * len);
  };
  const Vec3 end_tangent = a.curve.at(1).d1, cross_start = b.cross.at(0).p;
  if (mismatch(cross_start, -end_tangent))
    return where + "the cross derivative of side " + str(k) + " at its start, " +
           vec_str(cross_start) + ", is not minus the end tangent of side " + str(i) + ", " +
           vec_str(-end_tangent) + " (relative tolerance 1e-6)";
  const Vec3 start_tangent = b.curve.at(0).d1, cross_end = a.cross.at(1).p;
  if (mismatch(cross_end, start_tangent))
    return where + "the cross derivative of side " + str(i) + " at its end, " + vec_str(cross_end) +
           ", is not the start tangent of side " + str(k) + ", " + vec_str(start_tangent) +
           " (relative tolerance 1e-6)";
  return "";
}

int ribbon_reflex_corner(const std::vector<RibbonSide>& sides) {
  const std::vector<RibbonCurves> u = unit_sides(sides);
  const int n = static_cast<int>(u.size());
  Vec3 normal(0);
  for (int i = 0; i < n; ++i) normal += glm::cross(u[i].curve.at(0).p, u[i].curve.at(1).p);
  for (int i = 0; i < n; ++i) {
    const Vec3 in = u[i].curve.at(1).d1, out = u[(i + 1) % n].curve.at(0).d1;
    if (!(glm::dot(glm::cross(in, out), normal) > 0)) return i;
  }
  return -1;
}

RibbonPatch::DomainChoice RibbonPatch::choose_domain(RibbonScheme scheme,
                                                     const std::vector<RibbonSide>& sides,
                                                     const RibbonPatchOptions& o) {
  const std::size_t n = sides.size();
  if (n < 3 || n > std::size_t(RibbonPatch::kMaxSides))
    throw std::invalid_argument("a ribbons patch has 3 to " + str(RibbonPatch::kMaxSides) +
                                " sides, this one has " + std::to_string(n));
  if (domain_follows_curves(scheme, o))
    if (const auto v = transfinite::angular_domain(unit_sides(sides)))
      return {ConvexPolygonDomain(*v), transfinite::angular_domain_centre(*v)};
  if (!o.domain)  // the regular n-gon, centred at (0, 0) exactly
    return {ConvexPolygonDomain::regular(int(n)), Vec2(0)};
  if (o.domain->size() != n)
    throw std::invalid_argument("the domain has " + std::to_string(o.domain->size()) +
                                " vertices for " + std::to_string(n) + " sides");
  ConvexPolygonDomain d(*o.domain);
  Vec2 c(0);
  for (const Vec2& v : d.vertices()) c += v;
  return {std::move(d), c / double(n)};
}

RibbonPatch::RibbonPatch(RibbonScheme scheme, std::vector<RibbonSide> sides,
                         RibbonPatchOptions options)
    : scheme_(scheme),
      sides_(std::move(sides)),
      options_(std::move(options)),
      domain_(ConvexPolygonDomain::regular(3)),  // placeholders until set_domain below
      params_(domain_.vertices(), Vec2(0)) {
  set_domain(choose_domain(scheme_, sides_, options_));
  if ((options_.midpoint || options_.fullness != 1) && !transfinite::has_central_point(scheme_))
    throw std::invalid_argument(
        "a midpoint or fullness is a setting of the midpoint schemes "
        "only, not of " +
        std::string(transfinite::ribbon_scheme_name(scheme_)));
  if (!std::isfinite(options_.fullness))
    throw std::invalid_argument("the fullness must be a finite number");
  unit_curves_ = unit_sides(sides_);
  const int n = static_cast<int>(sides_.size());
  if (options_.check_corners) {
    for (int i = 0; i < n; ++i)
      if (const std::string why = ribbon_corner_problem(sides_, i); !why.empty())
        throw std::invalid_argument(why);
    if (const int c = ribbon_reflex_corner(sides_); c >= 0)
      throw std::invalid_argument(
          "corner " + str(c) + " is reflex (the boundary turns away from the face there): the " +
          std::string(transfinite::ribbon_scheme_name(scheme_)) +
          " scheme needs a convex face (use a gb-ribbons patch for concave ones)");
  }
  for (const RibbonSide& s : sides_) {
    offsets_.push_back(points_.size());
    points_.insert(points_.end(), s.curve.points.begin(), s.curve.points.end());
    offsets_.push_back(points_.size());
    points_.insert(points_.end(), s.cross.points.begin(), s.cross.points.end());
  }
  if (options_.midpoint) points_.push_back(*options_.midpoint);
  rebuild();
}

void RibbonPatch::set_domain(DomainChoice d) {
  domain_ = std::move(d.polygon);
  params_ = transfinite::PolygonParameters(domain_.vertices(), d.centre);
  diameter_ = 0;
  for (const Vec2& a : domain_.vertices())
    for (const Vec2& b : domain_.vertices()) diameter_ = std::max(diameter_, glm::length(a - b));
}

namespace {

// The central control point C that puts `midpoint` (or the default midpoint moved by the
// fullness) on the surface at
// the domain centre: C = (M - S0(centre)) / deficiency(centre).
Vec3 solve_central_point(RibbonScheme scheme, const RibbonSet& r,
                         const transfinite::PolygonParameters& params, const std::optional<Vec3>& m,
                         double fullness) {
  if (!transfinite::has_central_point(scheme)) return Vec3(0);
  Vec3 mid(0);
  if (m) {
    mid = *m;
  } else {
    for (int i = 0; i < r.size(); ++i) {
      const RibbonCurves& s = r.side(i);
      mid += s.curve.at(0.5).p + 0.25 * s.cross.at(0.5).p;  // I_i(1/2, 1/2), gamma(1/2) = 1/4
    }
    mid *= 1.0 / r.size();
    if (fullness != 1) {
      Vec3 corners(0);
      for (int i = 0; i < r.size(); ++i) corners += r.corner(i).point;
      corners *= 1.0 / r.size();
      mid = corners + fullness * (mid - corners);
    }
  }
  const SchemeInput in{r, params, Vec3(0)};
  const transfinite::DeficientSurface d =
      scheme == RibbonScheme::Midpoint ? transfinite::midpoint_surface(in, params.centre())
                                       : transfinite::midpoint_coons_surface(in, params.centre());
  if (std::abs(d.deficiency.f) < 1e-8) return mid;
  return (mid - d.s0.p) / d.deficiency.f;
}

// How far from a domain vertex (times the domain's diameter) its second derivatives are taken: far
// enough that the rational blends' rounding, magnified by the inverse square of the distance,
// stays near 1e-8 of the derivatives.
constexpr double kVertexOffset = 1e-4;

// The scheme at x with the limits at the domain vertices (see ribbon_patch.hpp).
SurfaceJet evaluate_with(RibbonScheme scheme, const SchemeInput& in, double diameter, Vec2 x) {
  const transfinite::PolygonParameters& d = in.domain;
  const int n = d.size();
  for (int i = 0; i < n; ++i) {
    if (!(glm::length(x - d.vertex(i)) <= 1e-12 * diameter)) continue;
    const Vec2 a = d.vertex(i) - d.vertex(i - 1), b = d.vertex(i + 1) - d.vertex(i);
    const Vec3 ta = in.ribbons.side(i).curve.at(1).d1, tb = in.ribbons.side(i + 1).curve.at(0).d1;
    const double det = a.x * b.y - a.y * b.x;
    const Vec2 towards = glm::normalize(d.centre() - d.vertex(i));
    SurfaceJet s =
        transfinite::scheme_surface(scheme, in, d.vertex(i) + kVertexOffset * diameter * towards);
    s.p = in.ribbons.corner(i).point;
    s.su = (ta * b.y - tb * a.y) / det;
    s.sv = (tb * a.x - ta * b.x) / det;
    return s;
  }
  return transfinite::scheme_surface(scheme, in, x);
}

}  // namespace

void RibbonPatch::rebuild() {
  ribbons_ = std::make_shared<RibbonSet>(unit_curves_, options_.twists);
  central_ = solve_central_point(scheme_, *ribbons_, params_, options_.midpoint, options_.fullness);
}

ControlPointKind RibbonPatch::kind(std::size_t k) const {
  if (options_.midpoint && k + 1 == points_.size()) return ControlPointKind::Central;
  const auto it = std::upper_bound(offsets_.begin(), offsets_.end(), k);
  const std::size_t slot = std::size_t(it - offsets_.begin()) - 1;
  return slot % 2 == 0 ? ControlPointKind::Boundary : ControlPointKind::Inner;
}

void RibbonPatch::set_control_point(std::size_t k, const Vec3& p) {
  points_.at(k) = p;
  if (options_.midpoint && k + 1 == points_.size()) {
    options_.midpoint = p;
  } else {
    const auto it = std::upper_bound(offsets_.begin(), offsets_.end(), k);
    const std::size_t slot = std::size_t(it - offsets_.begin()) - 1, j = k - offsets_[slot];
    RibbonSide& side = sides_[slot / 2];
    RibbonCurves& unit = unit_curves_[slot / 2];
    if (slot % 2 == 0) {
      side.curve.points[j] = p;
      unit.curve.spline().points[j] = p;
      if (domain_follows_curves()) set_domain(choose_domain(scheme_, sides_, options_));
    } else {
      side.cross.points[j] = p;
      unit.cross.spline().points[j] = p;
    }
  }
  rebuild();
}

SurfaceJet RibbonPatch::evaluate(Vec2 x) const {
  return evaluate_with(scheme_, {*ribbons_, params_, central_}, diameter_, x);
}

RibbonSet RibbonPatch::ribbon_set_of(const std::vector<Vec3>& points) const {
  std::vector<RibbonCurves> curves = unit_curves_;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    auto& cp = curves[i].curve.spline().points;
    auto& xp = curves[i].cross.spline().points;
    std::copy_n(points.begin() + std::ptrdiff_t(offsets_[2 * i]), cp.size(), cp.begin());
    std::copy_n(points.begin() + std::ptrdiff_t(offsets_[2 * i + 1]), xp.size(), xp.begin());
  }
  return RibbonSet(std::move(curves), options_.twists);
}

SurfaceJet RibbonPatch::evaluate_points(const std::vector<Vec3>& points, Vec2 x) const {
  const RibbonSet r = ribbon_set_of(points);
  const std::optional<Vec3> m =
      options_.midpoint ? std::optional<Vec3>(points.back()) : std::nullopt;
  const Vec3 c = solve_central_point(scheme_, r, params_, m, options_.fullness);
  return evaluate_with(scheme_, {r, params_, c}, diameter_, x);
}

void RibbonPatch::basis(Vec2 x, std::span<Jet> out) const {
  // phi_k is the surface of the unit point in place of control point k and zero elsewhere; three
  // at a time, one per coordinate.
  const std::size_t n = size();
  std::vector<Vec3> unit(n, Vec3(0));
  for (std::size_t k = 0; k < n; k += 3) {
    for (std::size_t c = 0; c < 3 && k + c < n; ++c) unit[k + c][int(c)] = 1;
    const SurfaceJet s = evaluate_points(unit, x);
    for (std::size_t c = 0; c < 3 && k + c < n; ++c) {
      out[k + c] = component(s, int(c));
      unit[k + c] = Vec3(0);
    }
  }
}

void RibbonPatch::influence(std::size_t k, std::span<const Vec2> xs, std::span<Jet> out) const {
  std::vector<Vec3> unit(size(), Vec3(0));
  unit.at(k) = Vec3(1, 0, 0);
  const RibbonSet r = ribbon_set_of(unit);
  const std::optional<Vec3> m = options_.midpoint ? std::optional<Vec3>(unit.back()) : std::nullopt;
  const SchemeInput in{r, params_, solve_central_point(scheme_, r, params_, m, options_.fullness)};
  for (std::size_t i = 0; i < xs.size() && i < out.size(); ++i)
    out[i] = component(evaluate_with(scheme_, in, diameter_, xs[i]), 0);
}

std::vector<BezierCurve> RibbonPatch::boundary_curves() const {
  std::vector<BezierCurve> out;
  for (const RibbonSide& s : sides_) out.emplace_back(s.curve.points);
  return out;
}

bool RibbonPatch::bezier_sides() const {
  return std::all_of(sides_.begin(), sides_.end(),
                     [](const RibbonSide& s) { return s.curve.type == CurveType::Bezier; });
}

Vec3 RibbonPatch::boundary_point(int side, double t) const {
  return unit_curves_.at(std::size_t(side)).curve.at(t).p;
}

}  // namespace pl
