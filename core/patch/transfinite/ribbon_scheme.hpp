// The ribbon-based transfinite schemes PatchLab evaluates, their names in the scene format and
// the one entry point that evaluates a scheme at a domain point. Each scheme lives in its own
// file (side_based.cpp, corner_based.cpp, ...) with its paper in the first comment.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "core/patch/surface_jet.hpp"
#include "core/patch/transfinite/polygon_parameters.hpp"
#include "core/patch/transfinite/ribbon_set.hpp"

namespace pl::transfinite {

enum class RibbonScheme {
  SideBased,
  CornerBased,
  GeneralizedCoons,
  CompositeRibbon,
  Midpoint,
  MidpointCoons,
  Elastic
};

// "side-based", "corner-based", "generalized-coons", "composite-ribbon", "midpoint",
// "midpoint-coons", "elastic".
std::string_view ribbon_scheme_name(RibbonScheme scheme);
std::optional<RibbonScheme> parse_ribbon_scheme(std::string_view name);
std::span<const RibbonScheme> all_ribbon_schemes();
// The midpoint schemes blend a central point with what their corner blend leaves (deficiency).
bool has_central_point(RibbonScheme scheme);

// What a scheme evaluates: the ribbons, the domain's parameters, and (midpoint schemes) the
// central control point C.
struct SchemeInput {
  const RibbonSet& ribbons;
  const PolygonParameters& domain;
  Vec3 central{0};
};

// The surface at domain point x, which must not be a domain vertex (the patch takes the limits
// there). The schemes, one file each:
SurfaceJet side_based_surface(const SchemeInput& in, Vec2 x);
SurfaceJet corner_based_surface(const SchemeInput& in, Vec2 x);
SurfaceJet generalized_coons_surface(const SchemeInput& in, Vec2 x);
SurfaceJet composite_ribbon_surface(const SchemeInput& in, Vec2 x);
// The midpoint schemes as S = S0 + deficiency C, with the central point C kept apart so that
// the patch can solve for the C that puts the chosen midpoint at the domain centre.
struct DeficientSurface {
  SurfaceJet s0;
  Jet deficiency;
};
DeficientSurface midpoint_surface(const SchemeInput& in, Vec2 x);
DeficientSurface midpoint_coons_surface(const SchemeInput& in, Vec2 x);
SurfaceJet elastic_surface(const SchemeInput& in, Vec2 x);

SurfaceJet scheme_surface(RibbonScheme scheme, const SchemeInput& in, Vec2 x);

}  // namespace pl::transfinite
