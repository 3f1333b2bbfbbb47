#include "core/network/gb_face.hpp"

#include <cmath>
#include <stdexcept>

#include "core/curve/bezier_curve.hpp"
#include "core/domain/convex_polygon.hpp"
#include "core/domain/domain_from_boundary.hpp"
#include "core/patch/gb/ribbon_elevation.hpp"

namespace pl {

namespace {

double arc_length(const std::array<Vec3, 4>& cp) {
  const BezierCurve c(std::vector<Vec3>(cp.begin(), cp.end()));
  double len = 0;
  Vec3 prev = c.point(0);
  for (int k = 1; k <= 128; ++k) {
    const Vec3 p = c.point(k / 128.0);
    len += glm::length(p - prev);
    prev = p;
  }
  return len;
}

Vec3 unit(Vec3 v) {
  const double l = glm::length(v);
  return l > 0 ? v / l : Vec3(0);
}

// Domain vertex k is the end of face side k; the polygons below list the ends in that order.
// Where the mean value coordinates of a side's end vertices sum to 0 or less inside the domain
// (behind a reflex corner: a notch, a U), a cubic ribbon with two layers would have a pole
// (GBRibbonPatch::sides_without_positive_pair); that side's ribbon gets a third layer, exactly
// (ribbon_with_layer: same boundary curve, same cross-boundary derivative, so the same G1 join),
// which makes its blend polynomial in the coordinates.
std::unique_ptr<GBRibbonPatch> make(const FaceRibbons& r, std::vector<Vec2> vertices) {
  ConcavePolygonDomain domain(std::move(vertices));
  std::vector<std::vector<std::vector<Vec3>>> ribbons;
  for (const CubicRibbon& s : r.sides)
    ribbons.push_back({std::vector<Vec3>(s.boundary.begin(), s.boundary.end()),
                       std::vector<Vec3>(s.inner.begin(), s.inner.end())});
  for (int i : GBRibbonPatch::sides_without_positive_pair(domain))
    ribbons[i] = ribbon_with_layer(ribbons[i]);
  return std::make_unique<GBRibbonPatch>(std::move(domain), ribbons);
}

}  // namespace

Vec3 face_normal(const FaceRibbons& ribbons) {
  // Newell normal of the boundary control polygon: the right-hand normal of the loop.
  std::vector<Vec3> poly;
  for (const CubicRibbon& s : ribbons.sides)
    poly.insert(poly.end(), s.boundary.begin(), s.boundary.end() - 1);
  Vec3 n(0);
  for (std::size_t i = 0; i < poly.size(); ++i)
    n += glm::cross(poly[i], poly[(i + 1) % poly.size()]);
  return unit(n);
}

std::vector<double> face_turning_angles(const FaceRibbons& ribbons) {
  const std::size_t n = ribbons.sides.size();
  const Vec3 normal = face_normal(ribbons);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CubicRibbon &a = ribbons.sides[i], &b = ribbons.sides[(i + 1) % n];
    const Vec3 t1 = unit(a.boundary[3] - a.boundary[2]), t2 = unit(b.boundary[1] - b.boundary[0]);
    const double angle = std::atan2(glm::length(glm::cross(t1, t2)), glm::dot(t1, t2));
    // A loop runs counter-clockwise around its normal: left turns are convex corners.
    out[i] = glm::dot(glm::cross(t1, t2), normal) < 0 ? -angle : angle;
  }
  return out;
}

FaceRibbons orient_reflex_corners(const FaceRibbons& in) {
  // The Chiyokura–Kimura field of side i is a(t) = k(t) b(t) + h(t) c(t) (k, h linear, b the
  // interpolated plane direction, c the edge derivative), its ends the neighbouring edges'
  // tangents. At a reflex corner that tangent points out of the face, so k changes sign along
  // the side and the ribbon folds over (SMI 2018: "interpolants should point towards the
  // interior"). Negating the end values of k and h there keeps a(t) in span(b(t), c(t)), the
  // plane the neighbouring face shares, so G1 across the edge is kept:
  //   a'(t) = a(t) - 2 t (k1 b(t) + h1 c(t))   (reflex end t = 1; mirrored for t = 0).
  FaceRibbons out = in;
  const std::size_t n = in.sides.size();
  const Vec3 normal = face_normal(in);
  const std::vector<double> turning = face_turning_angles(in);
  for (std::size_t i = 0; i < n; ++i) {
    const bool end_reflex = turning[i] < 0, start_reflex = turning[(i + n - 1) % n] < 0;
    if (!end_reflex && !start_reflex) continue;
    const CubicRibbon& r = in.sides[i];
    std::array<Vec3, 4> a;
    for (int j = 0; j < 4; ++j) a[j] = 3.0 * (r.inner[j] - r.boundary[j]);
    const Vec3 c[3] = {3.0 * (r.boundary[1] - r.boundary[0]), 3.0 * (r.boundary[2] - r.boundary[1]),
                       3.0 * (r.boundary[3] - r.boundary[2])};
    // b at either end: the end cross vector's part across the edge, turned into the face.
    const auto across = [&](Vec3 v, Vec3 cv) {
      const Vec3 perp = unit(v - glm::dot(v, cv) / glm::dot(cv, cv) * cv);
      return glm::dot(perp, glm::cross(normal, cv)) < 0 ? -perp : perp;
    };
    const Vec3 b0 = across(a[0], c[0]), b3 = across(a[3], c[2]);
    std::array<Vec3, 4> delta{Vec3(0), Vec3(0), Vec3(0), Vec3(0)};
    if (end_reflex) {
      const double k1 = glm::dot(a[3], b3), h1 = glm::dot(a[3], c[2]) / glm::dot(c[2], c[2]);
      // Cubic control vectors of t b(t) and t c(t).
      const Vec3 tb[4] = {Vec3(0), b0 / 3.0, (b0 + b3) / 3.0, b3};
      const Vec3 tc[4] = {Vec3(0), c[0] / 3.0, 2.0 * c[1] / 3.0, c[2]};
      for (int j = 0; j < 4; ++j) delta[j] -= 2.0 * (k1 * tb[j] + h1 * tc[j]);
    }
    if (start_reflex) {
      const double k0 = glm::dot(a[0], b0), h0 = glm::dot(a[0], c[0]) / glm::dot(c[0], c[0]);
      // Cubic control vectors of (1 - t) b(t) and (1 - t) c(t).
      const Vec3 sb[4] = {b0, (b0 + b3) / 3.0, b3 / 3.0, Vec3(0)};
      const Vec3 sc[4] = {c[0], 2.0 * c[1] / 3.0, c[2] / 3.0, Vec3(0)};
      for (int j = 0; j < 4; ++j) delta[j] -= 2.0 * (k0 * sb[j] + h0 * sc[j]);
    }
    for (int j = 0; j < 4; ++j) out.sides[i].inner[j] = r.boundary[j] + (a[j] + delta[j]) / 3.0;
  }
  return out;
}

namespace {

// The domain choice of gb_face_patch, building with make(ribbons, polygon).
template <class Make>
auto patch_over_chosen_domain(const FaceRibbons& input, GBDomainKind* used, Make&& make) {
  const int n = static_cast<int>(input.sides.size());
  if (n < 3) throw std::invalid_argument("a GB face needs at least 3 sides");
  const std::vector<double> turning = face_turning_angles(input);
  // A straight corner (two sides running on in one direction, as at a split edge's vertex)
  // counts as convex: its turning angle is zero up to rounding, and no concave domain has one.
  bool convex = true;
  for (double a : turning) convex = convex && a > -1e-9;
  if (convex) {
    if (used) *used = GBDomainKind::RegularPolygon;
    return make(input, ConvexPolygonDomain::regular(n).vertices());
  }
  const FaceRibbons ribbons = orient_reflex_corners(input);
  std::string why;
  std::vector<double> lengths;
  for (const CubicRibbon& s : ribbons.sides) lengths.push_back(arc_length(s.boundary));
  if (auto poly = angle_length_domain(lengths, turning)) {
    try {
      if (used) *used = GBDomainKind::AngleLength;
      return make(ribbons, *poly);
    } catch (const std::invalid_argument& e) {
      why = std::string("angle + arc-length domain: ") + e.what() + "; ";
    }
  }
  std::vector<Vec3> ends;
  for (const CubicRibbon& s : ribbons.sides) ends.push_back(s.boundary[3]);
  try {
    if (used) *used = GBDomainKind::Projection;
    return make(ribbons, project_to_best_fit_plane(ends));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("no usable GB domain (" + why + "projected domain: " + e.what() +
                                ")");
  }
}

}  // namespace

std::unique_ptr<GBRibbonPatch> gb_face_patch(const FaceRibbons& input, GBDomainKind* used) {
  return patch_over_chosen_domain(input, used, make);
}

FaceRibbons ribbons_as_filled(const FaceRibbons& input) {
  for (double a : face_turning_angles(input))
    if (!(a > -1e-9)) return orient_reflex_corners(input);
  return input;
}

}  // namespace pl
