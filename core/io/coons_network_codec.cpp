// {"type": "coons-network", "size": [ns, nt], "s": [nt rows of ns numbers],
//  "t": [ns columns of nt numbers], "data": [4*ns*nt vectors], "lengths": "network" | "equal"}
// data[(i*nt + j)*4 + q] is r, r_s, r_t, r_st (q = 0..3) of node (i, j); see
// coons_network_patch.hpp and docs/classic-types.md.
#include "core/io/classic_codec_util.hpp"
#include "core/io/patch_codec.hpp"
#include "core/patch/coons_network_patch.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

namespace {
std::vector<std::vector<double>> read_lines(const JsonNode& node, std::size_t count,
                                            std::size_t length) {
  std::vector<std::vector<double>> lines;
  for (const JsonNode& line : node.items(count)) {
    line.items(length);
    lines.push_back(read_numbers(line));
    for (std::size_t k = 1; k < length; ++k)
      if (!(lines.back()[k] > lines.back()[k - 1]))
        line.fail("parameters must increase strictly (value " + std::to_string(k) + ")");
  }
  return lines;
}
}  // namespace

std::unique_ptr<Patch> read_coons_network(const JsonNode& node) {
  node.allow_only({"type", "name", "size", "s", "t", "data", "lengths"});
  const auto size = node.at("size").items(2);
  const std::size_t ns = size[0].integer_in(2, 1000), nt = size[1].integer_in(2, 1000);
  auto s = read_lines(node.at("s"), nt, ns);
  auto t = read_lines(node.at("t"), ns, nt);
  const JsonNode data = node.at("data");
  data.items(4 * ns * nt);
  auto lengths = CoonsNetworkPatch::Lengths::Network;
  if (const auto l = node.find("lengths")) {
    const std::string v = l->string();
    if (v == "equal")
      lengths = CoonsNetworkPatch::Lengths::Equal;
    else if (v != "network")
      l->fail("unknown lengths \"" + v + "\" (allowed: network, equal)");
  }
  return std::make_unique<CoonsNetworkPatch>(ns, nt, std::move(s), std::move(t), data.points(),
                                             lengths);
}

void write_coons_network(const Patch& patch, nlohmann::json& out) {
  const auto& p = patch_ref<CoonsNetworkPatch>(patch);
  out["size"] = {p.ns(), p.nt()};
  out["s"] = p.s();
  out["t"] = p.t();
  out["data"] = points_json(p.control_points());
  out["lengths"] = p.lengths() == CoonsNetworkPatch::Lengths::Equal ? "equal" : "network";
}

}  // namespace

const PatchCodec kCoonsNetworkCodec{CoonsNetworkPatch::kType, read_coons_network,
                                    write_coons_network};

}  // namespace pl
