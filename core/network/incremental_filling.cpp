#include "core/network/incremental_filling.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>

#include "core/base/data_error.hpp"
#include "core/network/gb_face_interior.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

DataError named(const DataError& e, const std::string& source) {
  return e.source().empty() ? DataError(source, e.where(), e.message()) : e;
}

std::optional<Vec3> normal_of(const Network& n, std::size_t v) {
  return n.normals.empty() ? std::nullopt : n.normals[v];
}

// What a face's patch depends on besides its ribbons: every field but the loop (its geometry is
// in the ribbons) and the name.
bool same_fill_data(NetworkFace a, NetworkFace b) {
  a.loop.clear();
  b.loop.clear();
  a.name.clear();
  b.name.clear();
  return a == b;
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

std::size_t ribbons_hash(FaceScheme scheme, const FaceRibbons& r) {
  uint64_t h = 1469598103934665603ull ^ static_cast<uint64_t>(scheme);
  const auto mix = [&](double x) {
    h ^= std::bit_cast<uint64_t>(x + 0.0);  // +0.0: -0 and 0 hash alike, as they compare
    h *= 1099511628211ull;
    h ^= h >> 29;
  };
  for (const CubicRibbon& s : r.sides)
    for (int j = 0; j < 4; ++j)
      for (int c = 0; c < 3; ++c) {
        mix(s.boundary[j][c]);
        mix(s.inner[j][c]);
      }
  return static_cast<std::size_t>(h);
}

}  // namespace

std::vector<InteriorPointMove> interior_point_moves(const GBInteriorPatch& patch,
                                                    const NetworkFace& face) {
  const int n = patch.sides(), d = patch.degree();
  std::vector<Vec3> by(patch.net_size(), Vec3(0));
  for (const InteriorOffset& o : face.offsets) by.at(interior_point_index(n, d, o)) += o.by;
  std::vector<InteriorPointMove> moves;
  // Positions, not offsets, are compared: (D + by) - D need not be by in floating point, while
  // D + by is the same number however often it is computed.
  for (std::size_t k : patch.free_points()) {
    const Vec3 p = patch.control_point(patch.default_index(k)) + by[k];
    if (patch.control_point(k) != p) moves.push_back({k, p});
  }
  return moves;
}

void IncrementalFilling::note_patch(Face& face, const FacePatch& fp) {
  face.patch_side = fp.patch_side;
  const auto* interior = patch_as<GBInteriorPatch>(fp.patch.get());
  face.interior = interior != nullptr;
  face.centre = interior && interior->has_centre();
}

bool IncrementalFilling::interior_edit(int f, const Face& face, const NetworkFace& now) const {
  const Face& was = faces_[f];
  if (!was.interior || face.scheme != FaceScheme::GB || face.scheme != was.scheme ||
      !(face.ribbons == was.ribbons) || !gb_face_interior_form(now.degree, now.offsets))
    return false;
  NetworkFace a = now, b = network_.faces[f];
  a.offsets.clear();
  b.offsets.clear();
  if (!same_fill_data(a, b)) return false;
  // Offsets the patch could not carry go through the build, which names the problem.
  const int n = static_cast<int>(now.loop.size());
  for (const InteriorOffset& o : now.offsets)
    if (!interior_offset_problem(n, now.degree, o).empty() || (o.centre && !was.centre))
      return false;
  return true;
}

FacePatch IncrementalFilling::build(int face) const {
  return build_face_patch(face, faces_.at(face).scheme, faces_[face].ribbons, network_.faces[face],
                          source_);
}

IncrementalFilling::IncrementalFilling(std::optional<FaceScheme> scheme_override,
                                       std::string source)
    : scheme_override_(scheme_override), source_(std::move(source)) {}

FillingUpdate IncrementalFilling::update(const Network& network) {
  return same_structure(network) ? update_in_place(network) : rebuild(network);
}

std::optional<FillingUpdate> IncrementalFilling::update_interior(const Network& n,
                                                                 std::span<const int> faces) const {
  const Network& o = network_;
  if (n.vertices.size() != o.vertices.size() || n.edges.size() != o.edges.size() ||
      n.faces.size() != o.faces.size() || n.normals.size() != o.normals.size() ||
      o.faces.size() != faces_.size())
    return std::nullopt;
  std::vector<int> listed(faces.begin(), faces.end());
  sort_unique(listed);
  FillingUpdate up;
  for (int f : listed) {
    if (f < 0 || f >= static_cast<int>(n.faces.size())) return std::nullopt;
    const NetworkFace &now = n.faces[f], &was = o.faces[f];
    if (now == was) continue;  // e.g. dragged back to where it was
    // Its ribbons depend on the vertices, handles and normals, which the caller says are the
    // same: the face as filled is the face now, but for the offsets interior_edit() checks.
    if (now.loop != was.loop || now.name != was.name || !interior_edit(f, faces_[f], now))
      return std::nullopt;
    up.interior_edited.push_back(f);
  }
  return up;
}

std::vector<InteriorOffset> IncrementalFilling::exchange_offsets(
    int face, std::vector<InteriorOffset> offsets) {
  return std::exchange(network_.faces.at(std::size_t(face)).offsets, std::move(offsets));
}

bool IncrementalFilling::same_structure(const Network& n) const {
  const Network& o = network_;
  if (n.vertices.size() != o.vertices.size() || n.edges.size() != o.edges.size() ||
      n.faces.size() != o.faces.size())
    return false;
  if (!n.normals.empty() && n.normals.size() != n.vertices.size()) return false;  // invalid
  for (std::size_t e = 0; e < n.edges.size(); ++e)
    if (n.edges[e].v != o.edges[e].v) return false;
  for (std::size_t f = 0; f < n.faces.size(); ++f)
    if (n.faces[f].loop != o.faces[f].loop) return false;
  return true;
}

FillingUpdate IncrementalFilling::update_in_place(const Network& n) {
  FillingUpdate up;
  // What changed: vertices whose tangent plane may move, then the edges at them and the faces
  // using those edges (see the header).
  std::vector<int> vertices, edges, faces, renamed_edges;
  for (std::size_t v = 0; v < n.vertices.size(); ++v)
    if (n.vertices[v] != network_.vertices[v] || normal_of(n, v) != normal_of(network_, v))
      vertices.push_back(static_cast<int>(v));
  for (std::size_t e = 0; e < n.edges.size(); ++e) {
    const NetworkEdge &a = n.edges[e], &b = network_.edges[e];
    for (int k = 0; k < 2; ++k)
      if (a.handles[k] != b.handles[k]) vertices.push_back(a.v[k]);
    if (a.name != b.name) renamed_edges.push_back(static_cast<int>(e));
  }
  sort_unique(vertices);
  for (int v : vertices)
    for (int e : topology_.vertex_edges[v]) edges.push_back(e);
  sort_unique(edges);
  for (int e : edges)
    for (const EdgeUse& use : topology_.edge_faces[e]) faces.push_back(use.face);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const NetworkFace &a = n.faces[f], &b = network_.faces[f];
    if (a == b) continue;
    if (a.name != b.name) up.renamed.push_back(static_cast<int>(f));
    if (!same_fill_data(a, b)) faces.push_back(static_cast<int>(f));
  }
  sort_unique(faces);

  // New planes and fields are written in place over saved old values, put back if a DataError
  // interrupts, so a failed update leaves the filling as it was.
  std::vector<std::pair<int, TangentPlane>> old_planes;
  std::vector<std::pair<int, EdgeCrossTangents>> old_cross;
  std::vector<std::pair<int, Face>> new_faces;
  try {
    for (int v : vertices)
      old_planes.emplace_back(v, std::exchange(planes_[v], vertex_tangent_plane(n, topology_, v)));
    for (int e : edges)
      old_cross.emplace_back(
          e, std::exchange(cross_[e], edge_cross_tangents(n, topology_, planes_, e)));
    for (int f : faces) {
      Face face{
          resolve_scheme(n.faces[f], scheme_override_), face_ribbons(n, topology_, cross_, f), {}};
      if (face.scheme == faces_[f].scheme && face.ribbons == faces_[f].ribbons &&
          same_fill_data(n.faces[f], network_.faces[f]))
        continue;  // e.g. a handle moved back where it was: nothing to refill
      if (interior_edit(f, face, n.faces[f])) {
        up.interior_edited.push_back(f);
        continue;
      }
      FacePatch fp = build_face_patch(f, face.scheme, face.ribbons, n.faces[f], source_);
      note_patch(face, fp);
      new_faces.emplace_back(f, std::move(face));
      up.refilled.push_back(std::move(fp));
    }
  } catch (const DataError& e) {
    for (auto& [v, p] : old_planes) planes_[v] = p;
    for (auto& [e2, c] : old_cross) cross_[e2] = std::move(c);
    throw named(e, source_);
  }
  // Commit: only what changed is copied.
  for (int v : vertices) network_.vertices[v] = n.vertices[v];
  if (n.normals.size() != network_.normals.size()) {
    network_.normals = n.normals;
  } else if (!n.normals.empty()) {
    for (int v : vertices) network_.normals[v] = n.normals[v];
  }
  for (int v : vertices)
    for (int e : topology_.vertex_edges[v]) network_.edges[e].handles = n.edges[e].handles;
  for (int e : renamed_edges) network_.edges[e].name = n.edges[e].name;
  for (int f : faces) network_.faces[f] = n.faces[f];
  for (int f : up.renamed) network_.faces[f].name = n.faces[f].name;
  for (auto& [f, face] : new_faces) faces_[f] = std::move(face);
  up.previous_face.resize(faces_.size());
  for (std::size_t f = 0; f < faces_.size(); ++f) up.previous_face[f] = static_cast<int>(f);
  for (const FacePatch& fp : up.refilled) up.previous_face[fp.face] = -1;
  if (!vertices.empty()) {
    std::vector<ProjectedVertex> projected = pl::projected_vertices(planes_);
    up.projected_changed =
        projected.size() != projected_.size() ||
        !std::equal(projected.begin(), projected.end(), projected_.begin(),
                    [](const ProjectedVertex& a, const ProjectedVertex& b) {
                      return a.vertex == b.vertex && a.max_angle_deg == b.max_angle_deg;
                    });
    projected_ = std::move(projected);
  }
  return up;
}

FillingUpdate IncrementalFilling::rebuild(const Network& n) {
  FillingUpdate up;
  up.renumbered = true;
  NetworkTopology topology = validate_network(n, source_);
  std::vector<TangentPlane> planes;
  std::vector<EdgeCrossTangents> cross(n.edges.size());
  std::vector<Face> faces(n.faces.size());
  try {
    planes = vertex_tangent_planes(n, topology);
    for (std::size_t e = 0; e < n.edges.size(); ++e)
      cross[e] = edge_cross_tangents(n, topology, planes, static_cast<int>(e));
  } catch (const DataError& e) {
    throw named(e, source_);
  }
  // Faces filled before, by their ribbons: a face with the same ribbons and fill data keeps its
  // patch, whatever its index was.
  std::unordered_multimap<std::size_t, int> before;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    before.emplace(ribbons_hash(faces_[f].scheme, faces_[f].ribbons), static_cast<int>(f));
  std::vector<bool> taken(faces_.size(), false);
  up.previous_face.assign(n.faces.size(), -1);
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const int fi = static_cast<int>(f);
    Face& face = faces[f];
    face.scheme = resolve_scheme(n.faces[f], scheme_override_);
    face.ribbons = face_ribbons(n, topology, cross, fi);
    const auto [lo, hi] = before.equal_range(ribbons_hash(face.scheme, face.ribbons));
    for (auto it = lo; it != hi; ++it) {
      const int o = it->second;
      if (!taken[o] && faces_[o].scheme == face.scheme && faces_[o].ribbons == face.ribbons &&
          same_fill_data(network_.faces[o], n.faces[f])) {
        taken[o] = true;
        up.previous_face[f] = o;
        face.patch_side = faces_[o].patch_side;
        face.interior = faces_[o].interior;
        face.centre = faces_[o].centre;
        if (network_.faces[o].name != n.faces[f].name) up.renamed.push_back(fi);
        break;
      }
    }
    if (up.previous_face[f] >= 0) continue;
    FacePatch fp = build_face_patch(fi, face.scheme, face.ribbons, n.faces[f], source_);
    note_patch(face, fp);
    up.refilled.push_back(std::move(fp));
  }
  std::vector<ProjectedVertex> projected = pl::projected_vertices(planes);
  up.projected_changed = true;
  network_ = n;
  topology_ = std::move(topology);
  planes_ = std::move(planes);
  cross_ = std::move(cross);
  faces_ = std::move(faces);
  projected_ = std::move(projected);
  return up;
}

}  // namespace pl
