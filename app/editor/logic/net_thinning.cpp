#include "app/editor/logic/net_thinning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace pl {

namespace {

double at(const std::vector<double>& v, int i) {
  // Unknown sizes count as large: nothing is hidden that was not measured.
  return i >= 0 && i < int(v.size()) ? v[i] : std::numeric_limits<double>::infinity();
}

// The median of the finite values; infinity when there are none (nothing measured: shown).
double median(std::vector<double> v) {
  std::erase_if(v, [](double x) { return !std::isfinite(x); });
  if (v.empty()) return std::numeric_limits<double>::infinity();
  auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

void mark(std::vector<uint8_t>& flags, int i) {
  if (i >= 0 && i < int(flags.size())) flags[i] = 1;
}

}  // namespace

NetFocus net_focus(const std::vector<PointRef>& points, const std::vector<int>& edges,
                   const std::vector<int>& faces, const std::vector<int>& patches) {
  NetFocus f;
  f.edges = edges;
  f.faces = faces;
  f.patches = patches;
  for (const PointRef& r : points) {
    switch (r.kind) {
      case PointRef::Kind::NetworkVertex:
        f.vertices.push_back(r.index);
        break;
      case PointRef::Kind::EdgeHandle:
        f.edges.push_back(r.object);
        break;
      case PointRef::Kind::PatchPoint:
        f.patches.push_back(r.object);
        break;
      case PointRef::Kind::CurvePoint:  // curve points are never thinned out
        break;
      case PointRef::Kind::FreePoint:  // shows its face's net
        f.faces.push_back(r.object);
        break;
    }
  }
  return f;
}

NetThinning thin_control_net(const ScenePoints& pts, const SceneSurfaces& surfaces,
                             const Network* net, const NetScreenSizes& sizes, const NetFocus& focus,
                             double point_px) {
  NetThinning t;
  const double spacing = kNetPointSpacing * point_px;
  const std::size_t nv = net ? net->vertices.size() : 0, ne = net ? net->edges.size() : 0;

  // What the focus shows: vertices, edges (handles), surfaces (faces' nets), scene patches.
  std::vector<uint8_t> vertex_on(nv, 0), edge_on(ne, 0), patch_on;
  std::vector<uint8_t> surface_on(surfaces.surfaces.size(), 0);
  patch_on.assign(pts.patch_group.size(), 0);
  for (int p : focus.patches) mark(patch_on, p);
  for (int v : focus.vertices) mark(vertex_on, v);
  for (int e : focus.edges) mark(edge_on, e);
  if (net) {
    // A vertex in focus shows the handles of its edges; a face its edges' handles and vertices.
    std::vector<uint8_t> face_on(net->faces.size(), 0);
    for (int f : focus.faces) mark(face_on, f);
    for (std::size_t s = 0; s < surfaces.surfaces.size(); ++s) {
      const int f = surfaces.surfaces[s].face;
      if (f >= 0 && f < int(face_on.size()) && face_on[f]) surface_on[s] = 1;
    }
    for (std::size_t e = 0; e < ne; ++e) {
      const auto& v = net->edges[e].v;
      const bool at_vertex = (v[0] >= 0 && v[0] < int(nv) && vertex_on[v[0]]) ||
                             (v[1] >= 0 && v[1] < int(nv) && vertex_on[v[1]]);
      if (at_vertex) edge_on[e] = 1;
    }
    for (std::size_t f = 0; f < net->faces.size(); ++f) {
      if (!face_on[f]) continue;
      const auto& loop = net->faces[f].loop;
      for (int v : loop) mark(vertex_on, v);
    }
    if (!focus.faces.empty()) {
      // An edge joining two consecutive vertices of a focused face (its side) shows its handles.
      std::unordered_set<uint64_t> sides;
      auto key = [](int a, int b) {
        return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b));
      };
      for (int f : focus.faces) {
        if (f < 0 || f >= int(net->faces.size())) continue;
        const auto& loop = net->faces[f].loop;
        for (std::size_t k = 0; k < loop.size(); ++k)
          sides.insert(key(loop[k], loop[(k + 1) % loop.size()]));
      }
      for (std::size_t e = 0; e < ne; ++e)
        if (sides.count(key(net->edges[e].v[0], net->edges[e].v[1]))) edge_on[e] = 1;
    }
    // An edge in focus shows its vertices.
    for (std::size_t e = 0; e < ne; ++e)
      if (edge_on[e])
        for (int v : net->edges[e].v) mark(vertex_on, v);
  }

  // Sizes: a vertex by its shortest edge, an edge by its handle spacing, a group by its points'.
  std::vector<double> vertex_px(nv, std::numeric_limits<double>::infinity());
  for (std::size_t e = 0; e < ne; ++e)
    for (int v : net->edges[e].v)
      if (v >= 0 && v < int(nv))
        vertex_px[v] = std::min(vertex_px[v], at(sizes.edge_pixels, int(e)));
  std::vector<double> group_px(pts.groups.size(), 0.0);
  for (std::size_t s = 0; s < surfaces.surfaces.size(); ++s) {
    int g = s < pts.face_group.size() ? pts.face_group[s] : -1;
    const int p = surfaces.surfaces[s].patch;
    if (g < 0 && p >= 0 && p < int(pts.patch_group.size())) g = pts.patch_group[p];
    if (g >= 0) group_px[g] = std::max(group_px[g], at(sizes.surface_pixels, int(s)));
  }
  // Vertices, handles and faces' derived points are shown or hidden as a whole, by their
  // median size: per object, the ones at the threshold would come and go in a ragged pattern.
  std::vector<double> face_spacing;
  for (std::size_t g = 0; g < pts.groups.size(); ++g)
    if (pts.groups[g].owner.kind == PointOwner::Kind::Face && !pts.groups[g].ks.empty())
      face_spacing.push_back(group_px[g] / (std::sqrt(double(pts.groups[g].ks.size())) + 1));
  std::vector<double> handle_spacing;
  for (std::size_t e = 0; e < ne; ++e) handle_spacing.push_back(at(sizes.edge_pixels, int(e)) / 3);
  const bool vertices_shown = median(vertex_px) >= spacing;
  const bool handles_shown = median(handle_spacing) >= spacing;
  const bool derived_shown = median(face_spacing) >= spacing;
  std::vector<uint8_t> group_on(pts.groups.size(), 0);
  for (std::size_t g = 0; g < pts.groups.size(); ++g) {
    const ScenePoints::Group& gr = pts.groups[g];
    if (gr.owner.kind == PointOwner::Kind::Face) {
      const bool focused = gr.owner.index < int(surface_on.size()) && surface_on[gr.owner.index];
      group_on[g] = focused || derived_shown;
    } else {
      // An explicit patch by its own size: scenes hold a few, of any size.
      const bool focused = gr.owner.index < int(patch_on.size()) && patch_on[gr.owner.index];
      const double n = double(gr.ks.size());
      // n points across a square of the patch's diameter are about diameter / sqrt(n) apart.
      group_on[g] = focused || n == 0 || group_px[g] / (std::sqrt(n) + 1) >= spacing;
    }
  }
  std::vector<int> point_group(pts.positions.size(), -1);
  for (std::size_t g = 0; g < pts.groups.size(); ++g)
    for (std::size_t j = 0; j < pts.groups[g].ks.size(); ++j)
      if (pts.groups[g].first + j < point_group.size())
        point_group[pts.groups[g].first + j] = int(g);
  for (std::size_t g = 0; g < pts.groups.size(); ++g)  // a GB face's free points with its net
    for (std::size_t j = 0; j < pts.groups[g].free_count; ++j)
      if (pts.groups[g].free_first + j < point_group.size())
        point_group[pts.groups[g].free_first + j] = int(g);

  std::vector<uint8_t> hidden(pts.positions.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < pts.positions.size(); ++i) {
    const PointOwner& o = pts.owners[i];
    bool show = true;
    switch (o.kind) {
      case PointOwner::Kind::Vertex:
        show = o.index >= int(nv) || vertex_on[o.index] || vertices_shown;
        if (!show) ++t.hidden_vertices;
        break;
      case PointOwner::Kind::Edge:
        show = o.index >= int(ne) || edge_on[o.index] || handles_shown;
        if (!show) ++t.hidden_handles;
        break;
      case PointOwner::Kind::Patch:
      case PointOwner::Kind::Face:
        show = point_group[i] < 0 || group_on[point_group[i]];
        if (!show)
          ++(o.kind == PointOwner::Kind::Patch                ? t.hidden_patch
             : pts.kinds[i] == ControlPointKind::FreeInterior ? t.hidden_free
                                                              : t.hidden_derived);
        break;
      case PointOwner::Kind::Curve:  // few, and the only handle on a curve: always shown
        break;
    }
    hidden[i] = !show;
    any |= !show;
  }
  if (any) t.hidden = std::move(hidden);
  return t;
}

std::string NetThinning::note() const {
  if (hidden.empty()) return {};
  std::string what;
  auto add = [&](std::size_t n, const char* name) {
    if (n == 0) return;
    if (!what.empty()) what += ", ";
    what += std::to_string(n) + " " + name;
  };
  add(hidden_vertices, "vertices");
  add(hidden_handles, "handles");
  add(hidden_derived, "derived points");
  add(hidden_patch, "patch points");
  add(hidden_free, "free points");
  return "net: " + what + " hidden (too close on screen; zoom in or select)";
}

}  // namespace pl
