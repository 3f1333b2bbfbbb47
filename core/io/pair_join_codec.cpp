// {"type": "pair-join", "order": 1 | 2, "aux_degree": [d, m], "aux": [(d+1)(m+1) points],
//  "a": {"b1": [...], "c1": [...], "b2": [...], "c2": [...]}, "b": {...}}: see
// pair_join_patch.hpp; junction functions are Bernstein coefficients on [0,1].
#include "core/io/classic_codec_util.hpp"
#include "core/io/patch_codec.hpp"
#include "core/patch/pair_join_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

namespace {
JunctionFunctions read_junction(const JsonNode& node, int order) {
  node.allow_only({"b1", "c1", "b2", "c2"});
  JunctionFunctions j;
  j.b1 = read_numbers(node.at("b1"));
  j.c1 = read_numbers(node.at("c1"));
  if (order == 2) {
    j.b2 = read_numbers(node.at("b2"));
    j.c2 = read_numbers(node.at("c2"));
  }
  for (const char* key : {"b1", "c1", "b2", "c2"})
    if (const auto f = node.find(key); f && f->items().empty())
      f->fail("a junction function needs coefficients");
  return j;
}

nlohmann::json junction_json(const JunctionFunctions& j, int order) {
  nlohmann::json o = {{"b1", j.b1}, {"c1", j.c1}};
  if (order == 2) o["b2"] = j.b2, o["c2"] = j.c2;
  return o;
}
}  // namespace

std::unique_ptr<Patch> read_pair_join(const JsonNode& node) {
  node.allow_only({"type", "name", "order", "aux_degree", "aux", "a", "b"});
  const int order = node.at("order").integer_in(1, 2);
  const auto deg = node.at("aux_degree").items(2);
  const int d = deg[0].integer_in(1, 5), m = deg[1].integer_in(order, 5);
  const JsonNode aux = node.at("aux");
  aux.items((d + 1) * (m + 1));
  return std::make_unique<PairJoinPatch>(order, d, m, aux.points(),
                                         read_junction(node.at("a"), order),
                                         read_junction(node.at("b"), order));
}

void write_pair_join(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<PairJoinPatch>(patch);
  out["order"] = p.order();
  out["aux_degree"] = {p.aux_degree_u(), p.aux_degree_v()};
  out["aux"] = points_json(p.control_points());
  out["a"] = junction_json(p.junction(0), p.order());
  out["b"] = junction_json(p.junction(1), p.order());
}

}  // namespace

const PatchCodec kPairJoinCodec{PairJoinPatch::kType, read_pair_join, write_pair_join};

}  // namespace pl
