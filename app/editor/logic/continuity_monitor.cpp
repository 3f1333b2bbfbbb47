#include "app/editor/logic/continuity_monitor.hpp"

#include <algorithm>

namespace pl {

bool ContinuityMonitor::follow(const Scene& scene, std::span<const Input> inputs,
                               uint64_t revision) {
  std::vector<std::string> labels;
  for (const Input& in : inputs) labels.push_back(in.label);
  if (revision == revision_ && labels == labels_) return false;
  revision_ = revision;
  labels_ = std::move(labels);
  fillings_.clear();
  for (const Input& in : inputs) {
    Filling f;
    f.label = in.label;
    if (in.surfaces) f.report = analyze_scene(scene, *in.surfaces);
    for (std::size_t i = 0; i < f.report.edges.size(); ++i)
      if (f.worst < 0 ||
          f.report.edges[i].max_normal_angle_deg > f.report.edges[f.worst].max_normal_angle_deg)
        f.worst = static_cast<int>(i);
    fillings_.push_back(std::move(f));
  }
  return true;
}

bool ContinuityMonitor::follow(const Scene& scene, const SceneSurfaces& surfaces,
                               uint64_t revision) {
  const Input one[1] = {{"", &surfaces}};
  return follow(scene, one, revision);
}

const SceneReport& ContinuityMonitor::report() const {
  static const SceneReport none;
  return fillings_.empty() ? none : fillings_[0].report;
}

int ContinuityMonitor::worst_edge() const {
  return worst() < 0 ? -1 : fillings_[0].report.edges[worst()].edge;
}

std::vector<int> ContinuityMonitor::warnings(std::size_t f, double threshold_deg) const {
  std::vector<int> r;
  if (f >= fillings_.size()) return r;
  const auto& edges = fillings_[f].report.edges;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (edges[i].max_normal_angle_deg > threshold_deg) r.push_back(static_cast<int>(i));
  std::stable_sort(r.begin(), r.end(), [&](int a, int b) {
    return edges[a].max_normal_angle_deg > edges[b].max_normal_angle_deg;
  });
  return r;
}

int ContinuityMonitor::warned_edge(std::size_t f, double threshold_deg) const {
  if (f >= fillings_.size() || fillings_[f].worst < 0) return -1;
  const EdgeReport& e = fillings_[f].report.edges[fillings_[f].worst];
  return e.max_normal_angle_deg > threshold_deg ? e.edge : -1;
}

bool ContinuityMonitor::any_warning(double threshold_deg) const {
  for (std::size_t f = 0; f < fillings_.size(); ++f)
    if (warned_edge(f, threshold_deg) >= 0) return true;
  return false;
}

}  // namespace pl
