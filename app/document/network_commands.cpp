#include "app/document/network_commands.hpp"

#include <algorithm>

#include "core/base/data_error.hpp"
#include "core/network/network_filling.hpp"
#include "core/scene/network_edit.hpp"

namespace pl {

namespace {

std::string str(int i) {
  return std::to_string(i);
}

std::string list(const std::vector<int>& xs) {
  std::string s;
  for (std::size_t i = 0; i < xs.size(); ++i)
    s += (i == 0 ? "" : i + 1 == xs.size() ? " and " : ", ") + str(xs[i]);
  return s;
}

Network& network_of(Scene& scene) {
  if (!scene.network) throw EditRefused("the scene has no curve network");
  return *scene.network;
}

// The edited network must be one the reader accepts and the filling can fill near `vertices`
// (in the network's current indices); otherwise the edit is refused with the reason.
void check_network(const Network& net, std::vector<int> vertices) {
  try {
    const NetworkTopology topo = validate_network(net, "");
    std::erase_if(vertices, [&](int v) { return v < 0 || v >= int(net.vertices.size()); });
    check_fillable_near(net, topo, vertices, "");
  } catch (const DataError& e) {
    throw EditRefused("the edit would leave a network that cannot be filled: " +
                      std::string(e.what()));
  }
}

}  // namespace

void AddVertexCommand::apply(Scene& scene) {
  if (!scene.network) scene.network.emplace();
  vertex_ = add_vertex(*scene.network, position_);
}

void AddEdgeCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  const int n = int(net.vertices.size());
  const bool exist = a_ >= 0 && a_ < n && b_ >= 0 && b_ < n;  // else add_edge says which not
  edge_ = add_edge(net, a_, b_, exist ? new_edge_handles(net, a_, b_) : std::array<Vec3, 2>{});
  check_network(net, {a_, b_});
}

std::string AddEdgeCommand::label() const {
  return "add edge " + str(edge_) + " (vertices " + str(a_) + " and " + str(b_) + ")";
}

std::unique_ptr<MakeFaceCommand> MakeFaceCommand::from_edges(std::vector<int> edges,
                                                             std::optional<Vec3> towards) {
  auto c = std::make_unique<MakeFaceCommand>(std::vector<int>{}, towards);
  c->edges_ = std::move(edges);
  return c;
}

void MakeFaceCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  if (!edges_.empty()) loop_ = loop_of_edges(net, edges_);
  // Check the loop before adding edges, so a refusal names the request's problem.
  if (loop_.size() < 3)
    throw EditRefused("a face needs at least 3 vertices, got " + str(int(loop_.size())));
  for (std::size_t i = 0; i < loop_.size(); ++i) {
    if (loop_[i] < 0 || loop_[i] >= int(net.vertices.size()))
      throw EditRefused("vertex " + str(loop_[i]) + " does not exist");
    if (std::count(loop_.begin(), loop_.end(), loop_[i]) > 1)
      throw EditRefused("vertex " + str(loop_[i]) + " appears twice in the face's loop");
  }
  for (const auto& [a, b] : missing_loop_edges(net, loop_)) {
    add_edge(net, a, b, new_edge_handles(net, a, b));
    ++new_edges_;
  }
  face_ = add_face(net, loop_, towards_);
  check_network(net, net.faces[face_].loop);
}

std::string MakeFaceCommand::label() const {
  std::string s = "make face " + str(face_) + " (" + str(int(loop_.size())) + " sides";
  if (new_edges_ > 0) s += ", " + str(new_edges_) + (new_edges_ == 1 ? " new edge" : " new edges");
  return s + ")";
}

void FillHolesCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  faces_ = fill_holes(net, 3, max_sides_);
  std::vector<int> vertices;
  for (int f : faces_)
    vertices.insert(vertices.end(), net.faces[f].loop.begin(), net.faces[f].loop.end());
  check_network(net, vertices);
}

std::string FillHolesCommand::label() const {
  return faces_.size() == 1 ? "fill hole: face " + list(faces_)
                            : "fill holes: faces " + list(faces_);
}

void DeleteCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  // The vertices left next to what goes: their planes and faces change.
  std::vector<int> near;
  for (int e : edges_)
    if (e >= 0 && e < int(net.edges.size()))
      near.insert(near.end(), net.edges[e].v.begin(), net.edges[e].v.end());
  for (int f : faces_)
    if (f >= 0 && f < int(net.faces.size()))
      near.insert(near.end(), net.faces[f].loop.begin(), net.faces[f].loop.end());
  for (int v : vertices_)
    if (v >= 0 && v < int(net.vertices.size()))
      for (int e : edges_at(net, v))
        near.insert(near.end(), net.edges[e].v.begin(), net.edges[e].v.end());
  removed_ = delete_elements(net, vertices_, edges_, faces_);
  // To the new indices (removed vertices drop out).
  std::vector<int> now;
  for (int v : near) {
    const auto gone = std::lower_bound(removed_.vertices.begin(), removed_.vertices.end(), v);
    if (gone != removed_.vertices.end() && *gone == v) continue;
    now.push_back(v - int(gone - removed_.vertices.begin()));
  }
  check_network(net, now);
}

std::string DeleteCommand::label() const {
  std::vector<std::string> parts;
  const auto part = [&](const std::vector<int>& xs, const char* one, const char* many) {
    if (!xs.empty())
      parts.push_back((xs.size() == 1 ? std::string(one) + " " : std::string(many) + " ") +
                      list(xs));
  };
  part(removed_.vertices, "vertex", "vertices");
  part(removed_.edges, "edge", "edges");
  part(removed_.faces, "face", "faces");
  std::string s = "delete";
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i == 0 ? " " : ", ") + parts[i];
  return parts.empty() ? "delete nothing" : s;
}

std::unique_ptr<DeleteCommand> delete_vertex_command(int v) {
  return std::make_unique<DeleteCommand>(std::vector{v}, std::vector<int>{}, std::vector<int>{});
}
std::unique_ptr<DeleteCommand> delete_edge_command(int e) {
  return std::make_unique<DeleteCommand>(std::vector<int>{}, std::vector{e}, std::vector<int>{});
}
std::unique_ptr<DeleteCommand> delete_face_command(int f) {
  return std::make_unique<DeleteCommand>(std::vector<int>{}, std::vector<int>{}, std::vector{f});
}

void SplitEdgeCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  if (edge_ < 0 || edge_ >= int(net.edges.size()))
    throw EditRefused("edge " + str(edge_) + " does not exist");
  // The normal of the plane the faces share at t, from the network as it is.
  std::optional<Vec3> normal;
  try {
    const NetworkTopology topo = validate_network(net, "");
    if (!topo.edge_faces[edge_].empty()) {
      std::vector<TangentPlane> planes(net.vertices.size());
      for (int v : net.edges[edge_].v) planes[v] = vertex_tangent_plane(net, topo, v);
      normal = edge_plane_normal(net, planes, edge_, t_);
    }
  } catch (const DataError& e) {
    throw EditRefused("cannot split edge " + str(edge_) + ": " + std::string(e.what()));
  }
  split_ = split_edge(net, edge_, t_, normal);
  // A face with a side more is another n-gon: its free points are other points, so moved ones
  // are put back (the degree stays).
  std::vector<int> reset;
  for (int f : split_.faces)
    if (!net.faces[f].offsets.empty()) {
      net.faces[f].offsets.clear();
      reset.push_back(f);
    }
  const int a = net.edges[edge_].v[0], b = net.edges[split_.edge].v[1];
  check_network(net, {split_.vertex, a, b});
  label_ = "split edge " + str(edge_) + ": new vertex " + str(split_.vertex) + ", new edge " +
           str(split_.edge);
  for (int f : split_.faces) {
    const NetworkFace& face = net.faces[f];
    const FaceScheme s = resolve_scheme(face, std::nullopt);
    label_ += "; face " + str(f) + " now has " + str(int(face.loop.size())) + " sides (" +
              (s == FaceScheme::GB        ? std::string("GB")
               : s == FaceScheme::Gregory ? std::string("Gregory")
                                          : scheme_keyword(s)) +
              ")";
    if (std::find(reset.begin(), reset.end(), f) != reset.end())
      label_ += ", its interior back at its defaults";
  }
}

void SetFaceSchemeCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  set_face_scheme(net, face_, scheme_);
  NetworkFace& face = net.faces[face_];
  if (resolve_scheme(face, std::nullopt) == FaceScheme::Gregory &&
      (face.degree != 3 || !face.offsets.empty())) {
    face.degree = 3;
    face.offsets.clear();
    interior_dropped_ = true;
  }
  check_network(net, face.loop);
}

void RenameCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  if (element_ == Element::Face)
    set_face_name(net, index_, name_);
  else
    set_edge_name(net, index_, name_);
}

std::string RenameCommand::label() const {
  return (element_ == Element::Face ? "rename face " : "rename edge ") + str(index_);
}

void SetVertexNormalCommand::apply(Scene& scene) {
  Network& net = network_of(scene);
  if (vertex_ < 0 || vertex_ >= int(net.vertices.size()))
    throw EditRefused("vertex " + str(vertex_) + " does not exist");
  if (normal_)
    turn_vertex_plane(net, vertex_, *normal_);
  else
    set_vertex_normal(net, vertex_, std::nullopt);
  check_network(net, {vertex_});
}

std::string SetVertexNormalCommand::label() const {
  return normal_ ? "fix the tangent plane of vertex " + str(vertex_)
                 : "fit the tangent plane of vertex " + str(vertex_);
}

std::string SetVertexNormalCommand::merge_key() const {
  return continuing_ ? "normal;" + str(vertex_) : std::string();
}

}  // namespace pl
