// Evaluation throughput of every face scheme on the same boundary: one network face (a wavy
// quadrilateral, which every scheme fills, Gregory included; and a pentagon for the schemes that
// fill more sides) filled by the scheme, every sample of its domain tessellation at the default
// density evaluated with first and second derivatives (evaluate_many on one thread), in million
// samples per second. The schemes are measured in one run, so their ratios are comparable even
// on a busy machine.
#include <cmath>
#include <string>

#include "bench_common.hpp"
#include "core/network/network_filling.hpp"
#include "core/patch/gb/shared_basis.hpp"
#include "core/scene/network_edit.hpp"

namespace pl::bench {

namespace {

Network ngon_network(int n, FaceScheme scheme) {
  Network net;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * (i + 0.5) / n;
    net.vertices.push_back({std::cos(a), std::sin(a), 0.1 * std::sin(3 * a)});
  }
  NetworkFace face;
  for (int i = 0; i < n; ++i) {
    const Vec3 p = net.vertices[i], q = net.vertices[(i + 1) % n], lift(0, 0, 0.05);
    net.edges.push_back(
        {{i, (i + 1) % n}, {p + (q - p) / 3.0 + lift, p + 2.0 * (q - p) / 3.0 + lift}, ""});
    face.loop.push_back(i);
  }
  face.scheme = scheme;
  net.faces.push_back(face);
  return net;
}

}  // namespace

void bench_schemes(const Options& o) {
  constexpr int kDensity = 32;  // patchlab's default --density
  for (int n : {4, 5}) {
    for (FaceScheme scheme : all_face_schemes()) {
      if (scheme == FaceScheme::Gregory && n > 4) continue;
      const Network net = ngon_network(n, scheme);
      const NetworkTopology topo = validate_network(net, "bench");
      const NetworkFilling filling = fill_network(net, topo, std::nullopt, "bench");
      const Patch& patch = *filling.faces.at(0).patch;
      const std::vector<Vec2> xs = patch.domain().tessellate(o.quick ? 4 : kDensity).points;
      std::vector<SurfaceJet> out(xs.size());
      const SharedBasisBypass alone;  // each scheme's own evaluation, no kept GB basis
      const double ms = median_ms(o.quick ? 1 : 7, [&] { patch.evaluate_many(xs, out); });
      const std::string name = "scheme_full_eval_msamples_per_s_" + scheme_keyword(scheme) +
                               (n == 4 ? "" : "_n" + std::to_string(n));
      figure(name.c_str(), double(xs.size()) / (ms * 1e3), "Msamples/s");
    }
  }
}

}  // namespace pl::bench
