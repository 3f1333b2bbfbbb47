#include "core/network/network_filling.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

#include "core/base/data_error.hpp"
#include "core/base/parallel_for.hpp"
#include "core/network/face_ribbons.hpp"
#include "core/network/gb_face.hpp"
#include "core/network/gb_face_interior.hpp"
#include "core/network/gregory_face.hpp"
#include "core/network/ribbon_face.hpp"
#include "core/network/tangent_planes.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {
std::string face_path(int f) {
  return "network.faces[" + std::to_string(f) + "]";
}
}  // namespace

FacePatch build_face_patch(int face, FaceScheme scheme, const FaceRibbons& ribbons,
                           const NetworkFace& data, const std::string& source) {
  FacePatch fp;
  fp.face = face;
  if (scheme == FaceScheme::Gregory) {
    fp.patch = gregory_face_patch(ribbons);
    fp.patch_side.resize(ribbons.sides.size());
    std::iota(fp.patch_side.begin(), fp.patch_side.end(), 0);  // face side i = domain side i
    return fp;
  }
  if (const std::optional<transfinite::RibbonScheme> rs = ribbon_scheme_of(scheme)) {
    try {
      fp.patch = ribbon_face_patch(ribbons, *rs, data.fullness);
    } catch (const std::invalid_argument& e) {
      throw DataError(source, face_path(face),
                      "cannot build the " + scheme_keyword(scheme) + " patch: " + e.what());
    }
    fp.patch_side.resize(ribbons.sides.size());
    std::iota(fp.patch_side.begin(), fp.patch_side.end(), 0);
    return fp;
  }
  // GB faces: the independent-ribbon GB patch from the same ribbons, over the regular n-gon
  // (convex faces) or a concave domain (core/network/gb_face.hpp); face side i = domain side i.
  try {
    fp.patch = gb_face_patch(ribbons, data.degree, data.offsets);
  } catch (const std::invalid_argument& e) {
    throw DataError(source, face_path(face), std::string("cannot build the GB patch: ") + e.what());
  }
  fp.patch_side.resize(ribbons.sides.size());
  std::iota(fp.patch_side.begin(), fp.patch_side.end(), 0);
  return fp;
}

void check_fillable_near(const Network& network, const NetworkTopology& topology,
                         std::span<const int> vertices, const std::string& source) {
  std::vector<int> edges, ends, faces;
  for (int v : vertices)
    for (int e : topology.vertex_edges.at(v)) {
      edges.push_back(e);
      for (int w : network.edges[e].v) ends.push_back(w);
      for (const EdgeUse& use : topology.edge_faces[e]) faces.push_back(use.face);
    }
  const auto unique = [](std::vector<int>& x) {
    std::sort(x.begin(), x.end());
    x.erase(std::unique(x.begin(), x.end()), x.end());
  };
  unique(edges);
  unique(ends);
  unique(faces);
  // Faces using the edges need the fields of all their sides, so those edges' planes too.
  std::vector<int> face_edges;
  for (int f : faces)
    for (const FaceSide& side : topology.face_sides[f]) {
      face_edges.push_back(side.edge);
      for (int w : network.edges[side.edge].v) ends.push_back(w);
    }
  unique(face_edges);
  unique(ends);
  try {
    std::vector<TangentPlane> planes(network.vertices.size());
    for (int v : ends) planes[v] = vertex_tangent_plane(network, topology, v);
    std::vector<EdgeCrossTangents> cross(network.edges.size());
    for (int e : face_edges) cross[e] = edge_cross_tangents(network, topology, planes, e);
    for (int f : faces)
      build_face_patch(f, resolve_scheme(network.faces[f], std::nullopt),
                       face_ribbons(network, topology, cross, f), network.faces[f], source);
  } catch (const DataError& e) {
    if (!e.source().empty()) throw;
    throw DataError(source, e.where(), e.message());
  }
}

NetworkFilling fill_network(const Network& network, const NetworkTopology& topology,
                            std::optional<FaceScheme> scheme_override, const std::string& source) {
  NetworkFilling out;
  std::vector<FaceScheme> schemes;
  for (std::size_t f = 0; f < network.faces.size(); ++f)
    schemes.push_back(resolve_scheme(network.faces[f], scheme_override));
  std::vector<FaceRibbons> ribbons;
  try {
    ribbons = build_face_ribbons(network, topology, out.projected_vertices);
  } catch (const DataError& e) {
    throw DataError(source, e.where(), e.message());  // the construction does not know the file
  }
  // The faces' patches are independent: built over the cores (a GB face's domain and patch take
  // about 0.2 ms), the first bad face reported whatever the number of threads.
  std::vector<std::optional<FacePatch>> built(network.faces.size());
  parallel_each(built.size(), 8, [&](std::size_t f) {
    built[f] =
        build_face_patch(static_cast<int>(f), schemes[f], ribbons[f], network.faces[f], source);
  });
  out.faces.reserve(built.size());
  for (auto& fp : built) out.faces.push_back(std::move(*fp));
  return out;
}

}  // namespace pl
