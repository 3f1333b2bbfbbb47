#include "app/document/curves_to_edges_command.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/curve/cubic_fit.hpp"

namespace pl {

namespace {

std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

// The diagonal of the bounding box of the curves' control points.
double curves_size(const Scene& scene, const std::vector<int>& curves) {
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (int c : curves)
    for (const Vec3& p : scene.curves[c].points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

// The vertex a span end lands on: the nearest within `snap`, else a new one there.
int land(Network& n, const Vec3& p, double snap) {
  int best = -1;
  double distance = snap;
  for (std::size_t v = 0; v < n.vertices.size(); ++v)
    if (const double d = glm::length(n.vertices[v] - p); d <= distance) best = int(v), distance = d;
  return best >= 0 ? best : add_vertex(n, p);
}

// The curve's chains: one, or three pieces of a closed curve.
std::vector<CubicChain> chains_of(const SceneCurve& c, double tolerance) {
  const Vec3 first = evaluate(c, c.t_min()).p, last = evaluate(c, c.t_max()).p;
  if (glm::length(first - last) > tolerance) return {cubic_chain(c, tolerance)};
  const double a = c.t_min(), h = c.t_max() - c.t_min();
  auto [one, rest] = curve_split(c, a + h / 3);
  auto [two, three] = curve_split(rest, a + 2 * h / 3);
  return {cubic_chain(one, tolerance), cubic_chain(two, tolerance), cubic_chain(three, tolerance)};
}

}  // namespace

void CurvesToEdgesCommand::apply(Scene& scene) {
  if (curves_.empty()) throw EditRefused("no curve to turn into network edges");
  std::vector<int> curves = curves_;
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  for (int c : curves)
    if (c < 0 || c >= static_cast<int>(scene.curves.size()))
      throw EditRefused("no curve " + std::to_string(c));
  size_ = curves_size(scene, curves);
  used_tolerance_ = tolerance_ ? *tolerance_ : kCurveFitRelativeTolerance * size_;
  if (!(used_tolerance_ > 0) || !std::isfinite(used_tolerance_))
    throw EditRefused("the fitting tolerance must be a positive number");
  if (!scene.network) scene.network = Network{};
  Network& n = *scene.network;
  edges_.clear();
  deviation_ = 0;
  for (int c : curves) {
    const std::string name = curve_name(scene.curves[c], c);
    std::vector<CubicChain> chains;
    try {
      chains = chains_of(scene.curves[c], used_tolerance_);
    } catch (const std::invalid_argument& e) {
      throw EditRefused(name + ": " + e.what());
    }
    for (const CubicChain& chain : chains) {
      deviation_ = std::max(deviation_, chain.deviation);
      for (std::size_t s = 0; s < chain.spans.size(); ++s) {
        const auto& b = chain.spans[s];
        const int from = land(n, b[0], used_tolerance_), to = land(n, b[3], used_tolerance_);
        if (from == to)
          throw EditRefused(name + ": span " + std::to_string(s) + " begins and ends at vertex " +
                            std::to_string(from) + " (a smaller tolerance keeps them apart)");
        if (const int e = edge_between(n, from, to); e >= 0)
          throw EditRefused(name + ": span " + std::to_string(s) + " would join vertices " +
                            std::to_string(from) + " and " + std::to_string(to) + ", which edge " +
                            std::to_string(e) + " already joins");
        // Landed on a vertex a little away: the handles move with their ends, so the end
        // tangents are the curve's.
        const Vec3 h0 = b[1] + (n.vertices[from] - b[0]), h1 = b[2] + (n.vertices[to] - b[3]);
        edges_.push_back(add_edge(n, from, to, {h0, h1}));
      }
    }
  }
  for (auto c = curves.rbegin(); c != curves.rend(); ++c)
    scene.curves.erase(scene.curves.begin() + *c);
}

std::string CurvesToEdgesCommand::label() const {
  std::string which;
  for (int c : curves_) which += (which.empty() ? "" : ", ") + std::to_string(c);
  const bool exact = deviation_ <= 1e-12 * size_;  // rounding: every span is the curve itself
  return (curves_.size() == 1 ? "curve " : "curves ") + which + " to " +
         std::to_string(edges_.size()) + " network edges (" +
         (exact ? std::string("exact") : "fitted within " + number(used_tolerance_)) + ")";
}

}  // namespace pl
