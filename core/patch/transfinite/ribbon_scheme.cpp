#include "core/patch/transfinite/ribbon_scheme.hpp"

#include "core/patch/transfinite/vec_jet.hpp"

namespace pl::transfinite {

namespace {
struct Entry {
  RibbonScheme scheme;
  std::string_view name;
};
constexpr Entry kEntries[] = {
    {RibbonScheme::SideBased, "side-based"},
    {RibbonScheme::CornerBased, "corner-based"},
    {RibbonScheme::GeneralizedCoons, "generalized-coons"},
    {RibbonScheme::CompositeRibbon, "composite-ribbon"},
    {RibbonScheme::Midpoint, "midpoint"},
    {RibbonScheme::MidpointCoons, "midpoint-coons"},
    {RibbonScheme::Elastic, "elastic"},
};
constexpr RibbonScheme kAll[] = {RibbonScheme::SideBased,        RibbonScheme::CornerBased,
                                 RibbonScheme::GeneralizedCoons, RibbonScheme::CompositeRibbon,
                                 RibbonScheme::Midpoint,         RibbonScheme::MidpointCoons,
                                 RibbonScheme::Elastic};
}  // namespace

std::string_view ribbon_scheme_name(RibbonScheme scheme) {
  for (const Entry& e : kEntries)
    if (e.scheme == scheme) return e.name;
  return "?";
}

std::optional<RibbonScheme> parse_ribbon_scheme(std::string_view name) {
  for (const Entry& e : kEntries)
    if (e.name == name) return e.scheme;
  return std::nullopt;
}

std::span<const RibbonScheme> all_ribbon_schemes() {
  return kAll;
}

bool has_central_point(RibbonScheme scheme) {
  return scheme == RibbonScheme::Midpoint || scheme == RibbonScheme::MidpointCoons;
}

SurfaceJet scheme_surface(RibbonScheme scheme, const SchemeInput& in, Vec2 x) {
  switch (scheme) {
    case RibbonScheme::SideBased:
      return side_based_surface(in, x);
    case RibbonScheme::CornerBased:
      return corner_based_surface(in, x);
    case RibbonScheme::GeneralizedCoons:
      return generalized_coons_surface(in, x);
    case RibbonScheme::CompositeRibbon:
      return composite_ribbon_surface(in, x);
    case RibbonScheme::Midpoint: {
      const DeficientSurface d = midpoint_surface(in, x);
      return d.s0 + d.deficiency * in.central;
    }
    case RibbonScheme::MidpointCoons: {
      const DeficientSurface d = midpoint_coons_surface(in, x);
      return d.s0 + d.deficiency * in.central;
    }
    case RibbonScheme::Elastic:
      return elastic_surface(in, x);
  }
  return {};
}

}  // namespace pl::transfinite
