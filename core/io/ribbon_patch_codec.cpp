// {"type": "ribbons", "scheme": S, "sides": [{"curve": C, "cross": C}, ...], "domain": [[u, v],
//  ...], "midpoint": [x, y, z], "twists": "exact"|"forward-difference"}: a face given by explicit
// ribbons and filled by a ribbon-based transfinite scheme (docs/patch-types.md). Each C is a
// curve object of the `curves` key (bezier, bspline or nurbs). Not "gb-ribbons".
#include <cmath>
#include <string>

#include "core/io/curve_codec.hpp"
#include "core/io/patch_codec.hpp"
#include "core/patch/patch_types.hpp"
#include "core/patch/transfinite/ribbon_patch.hpp"

namespace pl {

namespace {

using transfinite::RibbonScheme;

std::string scheme_names() {
  std::string out;
  for (RibbonScheme s : transfinite::all_ribbon_schemes())
    out += (out.empty() ? "" : ", ") + std::string(transfinite::ribbon_scheme_name(s));
  return out;
}

std::unique_ptr<Patch> read_ribbon_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "scheme", "sides", "domain", "midpoint", "fullness", "twists"});
  const JsonNode sn = node.at("scheme");
  const std::string name = sn.string();
  const auto scheme = transfinite::parse_ribbon_scheme(name);
  if (!scheme)
    sn.fail("unknown scheme \"" + printable(name) + "\" (allowed: " + scheme_names() + ")");
  const JsonNode sides_node = node.at("sides");
  const auto items = sides_node.items();
  if (items.size() < 3 || items.size() > std::size_t(RibbonPatch::kMaxSides))
    sides_node.fail("a ribbons patch has 3 to " + std::to_string(RibbonPatch::kMaxSides) +
                    " sides, this one has " + std::to_string(items.size()));
  std::vector<RibbonSide> sides;
  for (const JsonNode& s : items) {
    s.allow_only({"curve", "cross"});
    RibbonSide side{read_curve(s.at("curve")), read_curve(s.at("cross"))};
    for (const auto& [key, c] : {std::pair{"curve", &side.curve}, {"cross", &side.cross}})
      if (c->type != CurveType::Bezier && c->type != CurveType::BSpline &&
          c->type != CurveType::Nurbs)
        s.at(key).fail("a ribbon curve is bezier, bspline or nurbs, not " +
                       std::string(curve_type_name(c->type)));
    sides.push_back(std::move(side));
  }
  RibbonPatchOptions options;
  if (const auto d = node.find("domain")) {
    std::vector<Vec2> vertices;
    for (const JsonNode& v : d->items(items.size())) {
      const auto uv = v.items(2);
      vertices.emplace_back(uv[0].number(), uv[1].number());
    }
    options.domain = std::move(vertices);
  }
  if (const auto m = node.find("midpoint")) {
    if (!transfinite::has_central_point(*scheme))
      m->fail("a midpoint is a setting of the midpoint and midpoint-coons schemes, not of " + name);
    options.midpoint = m->point();
  }
  if (const auto f = node.find("fullness")) {
    if (!transfinite::has_central_point(*scheme))
      f->fail("fullness is a setting of the midpoint and midpoint-coons schemes, not of " + name);
    if (options.midpoint) f->fail("give a midpoint or a fullness, not both");
    options.fullness = f->number();
    if (std::abs(options.fullness) > 100) f->fail("the fullness lies in [-100, 100]");
  }
  if (const auto t = node.find("twists")) {
    const std::string v = t->string();
    if (v == "forward-difference")
      options.twists = transfinite::TwistEstimate::ForwardDifference;
    else if (v != "exact")
      t->fail("twists are \"exact\" or \"forward-difference\", not \"" + printable(v) + "\"");
  }
  // The constructor throws std::invalid_argument naming the corner or side; the scene reader
  // turns that into a DataError at this patch's path.
  return std::make_unique<RibbonPatch>(*scheme, std::move(sides), std::move(options));
}

void write_ribbon_patch(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<RibbonPatch>(patch);
  out["scheme"] = std::string(transfinite::ribbon_scheme_name(p.scheme()));
  nlohmann::json sides = nlohmann::json::array();
  for (const RibbonSide& s : p.sides())
    sides.push_back({{"curve", curve_json(s.curve)}, {"cross", curve_json(s.cross)}});
  out["sides"] = sides;
  if (!p.default_domain()) {
    nlohmann::json dom = nlohmann::json::array();
    for (const Vec2& v : p.polygon().vertices()) dom.push_back({v.x, v.y});
    out["domain"] = dom;
  }
  if (p.options().midpoint) out["midpoint"] = point_json(*p.options().midpoint);
  if (p.options().fullness != 1) out["fullness"] = p.options().fullness;
  if (p.options().twists == transfinite::TwistEstimate::ForwardDifference)
    out["twists"] = "forward-difference";
}

}  // namespace

const PatchCodec kRibbonPatchCodec{RibbonPatch::kType, read_ribbon_patch, write_ribbon_patch};

}  // namespace pl
