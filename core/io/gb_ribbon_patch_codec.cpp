// {"type": "gb-ribbons", "domain": [[u, v], ...], "ribbons": [{"degree": d, "layers": l,
//  "points": [...]}, ...]}: see docs/patch-types.md. Each ribbon lists its l rows of d + 1
// points, boundary row first; consecutive ribbons repeat their shared corner point.
#include "core/io/patch_codec.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

std::unique_ptr<Patch> read_gb_ribbon_patch(const JsonNode& node) {
  node.allow_only({"type", "name", "domain", "ribbons"});
  const auto dom = node.at("domain").items();
  if (dom.size() < 3 || dom.size() > 64) node.at("domain").fail("expected 3 to 64 domain vertices");
  std::vector<Vec2> vertices;
  for (const JsonNode& v : dom) {
    const auto uv = v.items(2);
    vertices.emplace_back(uv[0].number(), uv[1].number());
  }
  const auto rib = node.at("ribbons").items(dom.size());
  std::vector<std::vector<std::vector<Vec3>>> ribbons;
  for (const JsonNode& r : rib) {
    r.allow_only({"degree", "layers", "points"});
    const int d = r.at("degree").integer_in(1, GBRibbonPatch::kMaxDegree),
              l = r.at("layers").integer_in(2, GBRibbonPatch::kMaxLayers);
    const JsonNode pts = r.at("points");
    pts.items(static_cast<std::size_t>(l * (d + 1)));
    const std::vector<Vec3> p = pts.points();
    auto& rows = ribbons.emplace_back(l);
    for (int k = 0; k < l; ++k)
      rows[k].assign(p.begin() + k * (d + 1), p.begin() + (k + 1) * (d + 1));
  }
  // The domain and patch constructors throw std::invalid_argument; the scene reader turns that
  // into a DataError at this patch's path.
  return std::make_unique<GBRibbonPatch>(ConcavePolygonDomain(std::move(vertices)), ribbons);
}

void write_gb_ribbon_patch(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<GBRibbonPatch>(patch);
  nlohmann::json dom = nlohmann::json::array();
  for (const Vec2& v : p.polygon().vertices()) dom.push_back({v.x, v.y});
  out["domain"] = dom;
  nlohmann::json ribbons = nlohmann::json::array();
  for (const auto& r : p.ribbons()) {
    std::vector<Vec3> flat;
    for (const auto& row : r) flat.insert(flat.end(), row.begin(), row.end());
    ribbons.push_back({{"degree", static_cast<int>(r[0].size()) - 1},
                       {"layers", static_cast<int>(r.size())},
                       {"points", points_json(flat)}});
  }
  out["ribbons"] = ribbons;
}

}  // namespace

const PatchCodec kGBRibbonPatchCodec{GBRibbonPatch::kType, read_gb_ribbon_patch,
                                     write_gb_ribbon_patch};

}  // namespace pl
