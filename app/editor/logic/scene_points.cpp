#include "app/editor/logic/scene_points.hpp"

#include <map>
#include <unordered_set>

#include "app/cli/draw_scene_builder.hpp"
#include "core/patch/control_net_topology.hpp"

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
// lines and arrows. With `shared`, a boundary point found there exactly is that network point.
void add_group(ScenePoints& s, SegmentSet& segments, const Patch& patch, PointOwner owner,
               bool editable, int patch_index, const PointIndex* shared) {
  const ControlNetTopology t = control_net_topology(patch);
  ScenePoints::Group g;
  g.owner = owner;
  g.first = s.positions.size();
  g.first_arrow = s.arrows.size();
  std::vector<uint32_t> id(patch.size(), 0);
  for (std::size_t k = 0; k < patch.size(); ++k) {
    if (t.is_vector[k]) continue;
    const Vec3 p = patch.control_point(k);
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

ScenePoints collect_scene_points(const Scene& scene, const SceneSurfaces& surfaces) {
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
  // A network face: its boundary points are the network's (listed above); the rest are derived
  // from the network and only shown.
  for (std::size_t i = 0; i < surfaces.surfaces.size(); ++i) {
    const SceneSurface& surface = surfaces.surfaces[i];
    if (surface.face < 0) {
      s.face_group.push_back(-1);
      continue;
    }
    s.face_group.push_back(int(s.groups.size()));
    add_group(s, segments, surface.evaluator->patch(), {PointOwner::Kind::Face, int(i)}, false, -1,
              &network_points);
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
