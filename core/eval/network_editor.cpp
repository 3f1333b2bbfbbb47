#include "core/eval/network_editor.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "core/base/data_error.hpp"
#include "core/network/face_ribbons.hpp"

namespace pl {

namespace {
DataError with_source(const DataError& e, const std::string& source) {
  return DataError(source, e.where(), e.message());
}
}  // namespace

NetworkEditor::NetworkEditor(Network network, std::optional<FaceScheme> scheme, int density,
                             TessellationCache& cache, std::string source)
    : network_(std::move(network)), source_(std::move(source)) {
  topology_ = validate_network(network_, source_);
  try {
    planes_ = vertex_tangent_planes(network_, topology_);
    cross_.resize(network_.edges.size());
    for (std::size_t e = 0; e < network_.edges.size(); ++e)
      cross_[e] = edge_cross_tangents(network_, topology_, planes_, static_cast<int>(e));
  } catch (const DataError& e) {
    throw with_source(e, source_);
  }
  for (std::size_t f = 0; f < network_.faces.size(); ++f) {
    const int fi = static_cast<int>(f);
    schemes_.push_back(resolve_scheme(network_.faces[f], scheme));
    FacePatch fp = build_face_patch(fi, schemes_[f],
                                    face_ribbons(network_, topology_, cross_, fi), source_);
    tessellations_.push_back(cache.get(fp.patch->domain(), density));
    evaluators_.push_back(std::make_unique<PatchEvaluator>(std::move(fp.patch), tessellations_[f]));
    patch_side_.push_back(std::move(fp.patch_side));
  }
}

NetworkEditor::Update NetworkEditor::refresh(const std::vector<int>& vertices) {
  // The new planes and fields are written in place over saved old values, which are put back
  // if a DataError interrupts, so a failed move leaves the editor as it was. Nothing here is
  // proportional to the size of the network.
  std::set<int> edges, faces;
  for (int v : vertices)
    for (int e : topology_.vertex_edges[v]) edges.insert(e);
  std::vector<std::pair<int, TangentPlane>> old_planes;
  std::vector<std::pair<int, EdgeCrossTangents>> old_cross;
  std::vector<std::pair<int, FacePatch>> patches;
  try {
    for (int v : vertices) {
      TangentPlane p = vertex_tangent_plane(network_, topology_, v);
      old_planes.emplace_back(v, std::exchange(planes_[v], p));
    }
    for (int e : edges) {
      EdgeCrossTangents c = edge_cross_tangents(network_, topology_, planes_, e);
      old_cross.emplace_back(e, std::exchange(cross_[e], std::move(c)));
      for (const EdgeUse& use : topology_.edge_faces[e]) faces.insert(use.face);
    }
    for (int f : faces)
      patches.emplace_back(f,
                           build_face_patch(f, schemes_[f],
                                            face_ribbons(network_, topology_, cross_, f), source_));
  } catch (...) {
    for (auto& [v, p] : old_planes) planes_[v] = p;
    for (auto& [e, c] : old_cross) cross_[e] = std::move(c);
    throw;
  }
  Update up;
  for (auto& [f, fp] : patches) {
    PatchEvaluator& ev = *evaluators_[f];
    const auto& now = ev.patch().control_points();
    const auto& next = fp.patch->control_points();
    if (now.size() != next.size()) {  // a different layout cannot be moved point by point
      evaluators_[f] = std::make_unique<PatchEvaluator>(std::move(fp.patch), tessellations_[f]);
      up.faces.push_back(f);
      continue;
    }
    std::vector<PatchEvaluator::PointMove> moves;
    for (std::size_t k = 0; k < next.size(); ++k)
      if (now[k] != next[k]) moves.push_back({k, next[k]});
    ev.move_control_points(moves);
    up.moved_points += moves.size();
    if (!moves.empty()) up.faces.push_back(f);
  }
  return up;
}

NetworkEditor::Update NetworkEditor::move_vertex(int v, const Vec3& p) {
  const Vec3 old = network_.vertices.at(v), d = p - old;
  std::vector<Vec3> old_handles;
  for (int e : topology_.vertex_edges[v]) {
    Vec3& h = network_.edges[e].handles[network_.edges[e].v[0] == v ? 0 : 1];
    old_handles.push_back(h);
    h += d;
  }
  network_.vertices[v] = p;
  try {
    return refresh({v});
  } catch (const DataError& e) {
    network_.vertices[v] = old;
    for (std::size_t i = 0; i < old_handles.size(); ++i) {
      const int e2 = topology_.vertex_edges[v][i];
      network_.edges[e2].handles[network_.edges[e2].v[0] == v ? 0 : 1] = old_handles[i];
    }
    throw with_source(e, source_);
  }
}

NetworkEditor::Update NetworkEditor::move_handle(int e, int k, const Vec3& p) {
  NetworkEdge& ed = network_.edges.at(e);
  const Vec3 old = ed.handles.at(k);
  ed.handles[k] = p;
  try {
    return refresh({ed.v[k]});
  } catch (const DataError& err) {
    network_.edges[e].handles[k] = old;
    throw with_source(err, source_);
  }
}

}  // namespace pl
