#include "app/editor/logic/scene_points.hpp"

#include <map>
#include <unordered_set>

#include "render/draw_scene_builder.hpp"
#include "core/base/data_error.hpp"
#include "core/network/gb_face_free_points.hpp"
#include "core/network/incremental_filling.hpp"
#include "core/patch/control_net_topology.hpp"
#include "core/patch/patch_types.hpp"

namespace pl {

namespace {

uint32_t add(ScenePoints& s, const Vec3& p, ControlPointKind kind, std::optional<PointRef> ref,
             PointOwner owner) {
  s.positions.push_back(p);
  s.kinds.push_back(kind);
  s.refs.push_back(ref);
  s.owners.push_back(owner);
  return static_cast<uint32_t>(s.positions.size() - 1);
}

// Segments once each, whatever the order of their ends (two faces' nets share their boundary
// rows with the network's own polygon).
class SegmentSet {
 public:
  explicit SegmentSet(ScenePoints& s) : s_(s) {}
  void add(uint32_t a, uint32_t b) {
    if (a == b) return;
    if (a > b) std::swap(a, b);
    if (seen_.insert(uint64_t(a) << 32 | b).second) s_.segments.push_back({a, b});
  }

 private:
  ScenePoints& s_;
  std::unordered_set<uint64_t> seen_;
};

using PointIndex = std::map<std::array<double, 3>, uint32_t>;

// Adds one patch's points as a group: positions of `role` (refs from make_ref, or none), its net
// lines and arrows. With `shared`, a boundary point found there exactly is that network point;
// with `own`, any point found there exactly is that point (a face's free points).
ScenePoints::Group& add_group(ScenePoints& s, SegmentSet& segments, const Patch& patch,
                              PointOwner owner, bool editable, int patch_index,
                              const PointIndex* shared, const PointIndex* own = nullptr) {
  // A face with interior control draws its degree-d net (control_net_topology hides the rest).
  const ControlNetTopology t = control_net_topology(patch);
  const auto* interior = patch_as<GBInteriorPatch>(patch);
  ScenePoints::Group g;
  g.owner = owner;
  g.first = s.positions.size();
  g.first_arrow = s.arrows.size();
  std::vector<uint32_t> id(patch.size(), 0);
  for (std::size_t k = 0; k < patch.size(); ++k) {
    if (t.is_vector[k] || (k == 0 && interior && !interior->has_centre())) continue;
    const Vec3 p = patch.control_point(k);
    if (own) {
      const auto it = own->find({p.x, p.y, p.z});
      if (it != own->end()) {
        id[k] = it->second;
        continue;
      }
    }
    if (shared && patch.kind(k) == ControlPointKind::Boundary) {
      const auto it = shared->find({p.x, p.y, p.z});
      if (it != shared->end()) {
        id[k] = it->second;
        continue;
      }
    }
    id[k] = add(s, p, patch.kind(k),
                editable ? std::optional(PointRef::patch_point(patch_index, int(k))) : std::nullopt,
                owner);
    g.ks.push_back(uint32_t(k));
  }
  for (const auto& seg : t.segments) segments.add(id[seg[0]], id[seg[1]]);
  for (const DerivativeArrow& a : t.arrows) {
    s.arrows.push_back({patch.control_point(a.base), arrow_tip(patch, a), a.kind});
    s.arrow_base.push_back(id[a.base]);
    g.arrow_data.push_back(a);
  }
  s.groups.push_back(std::move(g));
  return s.groups.back();
}

// The free points of face f as the scene has them, from the filling's topology and planes; none
// for a face filled otherwise than GB (a Gregory face, or a GB face seen in the Gregory panel
// of the comparison) or whose defaults cannot be built.
std::vector<FreePoint> face_free_points(const Scene& scene, const Patch& patch,
                                        const NetworkTopology& topology,
                                        const std::vector<TangentPlane>& planes, int f,
                                        std::vector<EdgeCrossTangents>& cross) {
  if (!is_gb_face(scene, f) || patch.type().starts_with("gregory")) return {};
  const NetworkFace& face = scene.network->faces[f];
  std::vector<FreePoint> out;
  try {
    out = gb_face_free_points(face_ribbons_from_planes(*scene.network, topology, planes, f, cross),
                              face.degree, face.offsets);
  } catch (const std::exception&) {
    return {};
  }
  // A face too concave for the central point's weight has none.
  const auto* interior = patch_as<GBInteriorPatch>(patch);
  if (interior && !interior->has_centre())
    std::erase_if(out, [](const FreePoint& p) { return p.name.centre; });
  return out;
}

}  // namespace

std::vector<bool> ScenePoints::editable() const {
  std::vector<bool> e(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) e[i] = refs[i].has_value();
  return e;
}

int ScenePoints::find(const PointRef& ref) const {
  for (std::size_t i = 0; i < refs.size(); ++i)
    if (refs[i] && *refs[i] == ref) return static_cast<int>(i);
  return -1;
}

ScenePoints collect_scene_points(const Scene& scene, const SceneSurfaces& surfaces,
                                 const IncrementalFilling* filling) {
  ScenePoints s;
  SegmentSet segments(s);
  PointIndex network_points;
  if (scene.network) {
    const Network& net = *scene.network;
    std::vector<uint32_t> vertex_ids;
    for (std::size_t v = 0; v < net.vertices.size(); ++v) {
      const Vec3& p = net.vertices[v];
      vertex_ids.push_back(add(s, p, ControlPointKind::Boundary, PointRef::vertex(int(v)),
                               {PointOwner::Kind::Vertex, int(v)}));
      network_points.emplace(std::array<double, 3>{p.x, p.y, p.z}, vertex_ids.back());
    }
    for (std::size_t e = 0; e < net.edges.size(); ++e) {
      const NetworkEdge& edge = net.edges[e];
      const int ei = static_cast<int>(e);
      uint32_t h[2];
      for (int k = 0; k < 2; ++k) {
        const Vec3& p = edge.handles[k];
        h[k] = add(s, p, ControlPointKind::Boundary, PointRef::handle(ei, k),
                   {PointOwner::Kind::Edge, ei});
        network_points.emplace(std::array<double, 3>{p.x, p.y, p.z}, h[k]);
      }
      if (edge.v[0] >= 0 && edge.v[0] < int(vertex_ids.size()))
        segments.add(vertex_ids[edge.v[0]], h[0]);
      segments.add(h[0], h[1]);
      if (edge.v[1] >= 0 && edge.v[1] < int(vertex_ids.size()))
        segments.add(h[1], vertex_ids[edge.v[1]]);
    }
  }
  // Explicit patches once each (a Catmull–Clark surface is drawn as several surfaces of one
  // patch); all of their points are the user's.
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    s.patch_group.push_back(int(s.groups.size()));
    add_group(s, segments, *scene.patches[p].patch, {PointOwner::Kind::Patch, int(p)}, true, int(p),
              nullptr);
  }
  // A network face: its boundary points are the network's (listed above); a GB face's free
  // points are the user's; the rest are derived from the network and only shown.
  NetworkTopology own_topology;
  std::vector<TangentPlane> own_planes;
  if (scene.network && !filling) {
    try {
      own_topology = validate_network(*scene.network, "scene");
      own_planes = vertex_tangent_planes(*scene.network, own_topology);
    } catch (const DataError&) {
      own_topology = {};
    }
  }
  const NetworkTopology& topology = filling ? filling->topology() : own_topology;
  const std::vector<TangentPlane>& planes = filling ? filling->planes() : own_planes;
  std::vector<EdgeCrossTangents> cross;
  for (std::size_t i = 0; i < surfaces.surfaces.size(); ++i) {
    const SceneSurface& surface = surfaces.surfaces[i];
    if (surface.face < 0) {
      s.face_group.push_back(-1);
      continue;
    }
    s.face_group.push_back(int(s.groups.size()));
    const PointOwner owner{PointOwner::Kind::Face, int(i)};
    const Patch& patch = surface.evaluator->patch();
    std::vector<FreePoint> free;
    if (surface.face < int(topology.face_sides.size()))
      free = face_free_points(scene, patch, topology, planes, surface.face, cross);
    PointIndex own;
    const std::size_t free_first = s.positions.size();
    for (const FreePoint& p : free) {
      const Vec3 at = p.position();
      own.emplace(std::array<double, 3>{at.x, at.y, at.z},
                  add(s, at, ControlPointKind::FreeInterior,
                      PointRef::free_point(surface.face, p.name), owner));
    }
    ScenePoints::Group& g = add_group(s, segments, patch, owner, false, -1, &network_points, &own);
    g.face = surface.face;
    g.free_first = free_first;
    g.free_count = free.size();
  }
  // Free curves: every control point is the user's; consecutive points make the polygon (a
  // Hermite curve has two points and no polygon between them).
  for (std::size_t c = 0; c < scene.curves.size(); ++c) {
    const SceneCurve& curve = scene.curves[c];
    const auto base = static_cast<uint32_t>(s.positions.size());
    for (std::size_t k = 0; k < curve.points.size(); ++k)
      add(s, curve.points[k], ControlPointKind::Curve,
          PointRef::curve_point(static_cast<int>(c), static_cast<int>(k)),
          {PointOwner::Kind::Curve, static_cast<int>(c)});
    if (curve.type != CurveType::Hermite)
      for (std::size_t k = 1; k < curve.points.size(); ++k)
        segments.add(base + uint32_t(k - 1), base + uint32_t(k));
  }
  return s;
}

bool update_group(ScenePoints& s, std::size_t gi, const Patch& patch) {
  if (gi >= s.groups.size()) return false;
  const ScenePoints::Group& g = s.groups[gi];
  if (g.first + g.ks.size() > s.positions.size() ||
      g.first_arrow + g.arrow_data.size() > s.arrows.size())
    return false;
  for (std::size_t j = 0; j < g.ks.size(); ++j) {
    if (g.ks[j] >= patch.size() || patch.kind(g.ks[j]) != s.kinds[g.first + j]) return false;
    s.positions[g.first + j] = patch.control_point(g.ks[j]);
  }
  for (std::size_t j = 0; j < g.arrow_data.size(); ++j) {
    const DerivativeArrow& a = g.arrow_data[j];
    if (std::max(a.base, a.vector) >= patch.size()) return false;
    s.arrows[g.first_arrow + j] = {patch.control_point(a.base), arrow_tip(patch, a), a.kind};
  }
  return true;
}

bool update_free_points(ScenePoints& s, std::size_t gi, const Scene& scene, const Patch& patch,
                        const IncrementalFilling& filling, std::vector<EdgeCrossTangents>& cross) {
  if (gi >= s.groups.size()) return false;
  const ScenePoints::Group& g = s.groups[gi];
  if (g.face < 0 || g.free_first + g.free_count > s.positions.size()) return false;
  // A face listed without free points gains some only with a new patch (a scheme or degree
  // change), which update_group does not accept.
  if (g.free_count == 0) return true;
  if (g.face >= int(filling.topology().face_sides.size())) return false;
  const std::vector<FreePoint> free =
      face_free_points(scene, patch, filling.topology(), filling.planes(), g.face, cross);
  if (free.size() != g.free_count) return false;
  for (std::size_t j = 0; j < free.size(); ++j) {
    if (s.refs[g.free_first + j] != PointRef::free_point(g.face, free[j].name)) return false;
    s.positions[g.free_first + j] = free[j].position();
  }
  return true;
}

void make_control_net(const ScenePoints& s, bool only_shown, ControlNet& out) {
  out.points.clear();
  out.kinds.clear();
  out.roles.clear();
  out.segments.clear();
  const bool all = !only_shown || s.hidden.empty();
  std::vector<uint32_t> index;  // ScenePoints index -> net index (UINT32_MAX: left out)
  if (!all) index.assign(s.positions.size(), UINT32_MAX);
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    if (!all && !s.shown(i)) continue;
    if (!all) index[i] = uint32_t(out.points.size());
    out.points.push_back(s.positions[i]);
    out.kinds.push_back(s.kinds[i]);
    out.roles.push_back(s.refs[i] ? PointRole::Editable : PointRole::Derived);
  }
  for (const auto& seg : s.segments) {
    if (all) {
      out.segments.push_back(seg);
    } else if (index[seg[0]] != UINT32_MAX && index[seg[1]] != UINT32_MAX) {
      out.segments.push_back({index[seg[0]], index[seg[1]]});
    }
  }
}

void fill_overlays(const Scene& scene, const ScenePoints& points, DrawScene& draw) {
  make_control_net(points, false, draw.net);
  draw.arrows = points.arrows;
  draw.network_curves.clear();
  if (scene.network) draw.network_curves = network_polylines(*scene.network);
  draw.free_curves.clear();
  for (const SceneCurve& c : scene.curves) draw.free_curves.push_back(free_curve_polyline(c));
}

}  // namespace pl
