// Catmull-Clark limit surfaces: our face patches against OpenSubdiv's own limit stencils,
// against the uniform bicubic B-spline on regular faces, against uniformly refined meshes, and
// against finite differences; finite everywhere, including extraordinary vertices.
#include <gtest/gtest.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <cstdio>

#include "classic_test_util.hpp"
#include "core/curve/bspline_curve.hpp"
#include "core/domain/tessellation_cache.hpp"
#include "core/eval/patch_evaluator.hpp"
#include "core/eval/scene_evaluation.hpp"
#include "core/eval/scene_surfaces.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/catmull_clark_patch.hpp"

namespace pl {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
using test::max_abs;

struct Mesh {
  std::vector<Vec3> v;
  std::vector<std::vector<int>> f;
};

Mesh cube() {  // every vertex has valence 3: all corners extraordinary
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.v.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.f = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

Mesh grid(int n) {  // (n+1)^2 vertices, open, wavy heights; interior faces are regular
  Mesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.v.push_back(
          {double(i), double(j), 0.4 * std::sin(1.3 * i) * std::cos(0.9 * j) + 0.05 * i * j});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      m.f.push_back(
          {i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1});
  return m;
}

Mesh twisted_grid() {  // an open grid, twisted: boundary and corner vertices
  Mesh m = grid(4);
  // Twisted so that no face is planar.
  for (auto& p : m.v) p.z += 0.1 * p.x * p.y;
  return m;
}

std::unique_ptr<Far::TopologyRefiner> refiner_for(const Mesh& m) {
  std::vector<int> counts, idx;
  for (const auto& f : m.f)
    counts.push_back(int(f.size())), idx.insert(idx.end(), f.begin(), f.end());
  Far::TopologyDescriptor d;
  d.numVertices = int(m.v.size());
  d.numFaces = int(m.f.size());
  d.numVertsPerFace = counts.data();
  d.vertIndicesPerFace = idx.data();
  Sdc::Options o;
  o.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using F = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(F::Create(d, F::Options(Sdc::SCHEME_CATMARK, o)));
}

// OpenSubdiv's limit stencils (its own patch evaluation path) at (face, u, v).
std::vector<SurfaceJet> osd_limit(const Mesh& m, int face, const std::vector<Vec2>& uv) {
  auto r = refiner_for(m);
  Far::PatchTableFactory::Options po(10);
  po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  po.useInfSharpPatch = true;
  r->RefineAdaptive(po.GetRefineAdaptiveOptions());
  std::vector<double> s, t;
  for (const Vec2& x : uv) s.push_back(x.x), t.push_back(x.y);
  Far::LimitStencilTableFactoryReal<double>::LocationArray loc;
  loc.ptexIdx = face;
  loc.numLocations = int(uv.size());
  loc.s = s.data();
  loc.t = t.data();
  Far::LimitStencilTableFactoryReal<double>::Options lo;
  lo.generate1stDerivatives = true;
  lo.generate2ndDerivatives = true;
  std::unique_ptr<const Far::LimitStencilTableReal<double>> table(
      Far::LimitStencilTableFactoryReal<double>::Create(*r, {loc}, nullptr, nullptr, lo));
  std::vector<SurfaceJet> out(uv.size());
  for (std::size_t i = 0; i < uv.size(); ++i) {
    const auto st = table->GetLimitStencil(int(i));
    SurfaceJet& j = out[i];
    for (int k = 0; k < st.GetSize(); ++k) {
      const Vec3& p = m.v[st.GetVertexIndices()[k]];
      j.p += st.GetWeights()[k] * p;
      j.su += st.GetDuWeights()[k] * p;
      j.sv += st.GetDvWeights()[k] * p;
      j.suu += st.GetDuuWeights()[k] * p;
      j.suv += st.GetDuvWeights()[k] * p;
      j.svv += st.GetDvvWeights()[k] * p;
    }
  }
  return out;
}

double jet_diff(const SurfaceJet& a, const SurfaceJet& b) {
  return std::max({max_abs(a.p - b.p), max_abs(a.su - b.su), max_abs(a.sv - b.sv),
                   max_abs(a.suu - b.suu), max_abs(a.suv - b.suv), max_abs(a.svv - b.svv)});
}

TEST(ClassicCatmullClark, AgreesWithOpenSubdivLimitStencils) {
  // Everywhere the full jet must agree. Exactly at a face corner on an extraordinary vertex the
  // Gregory end cap's rational blend is 0/0 and its second derivatives are a limit that the two
  // OpenSubdiv paths approximate differently (~1e-9): there position and first derivatives are
  // compared, and the second-derivative difference is reported.
  double interior = 0, corner_d01 = 0, corner_d2 = 0;
  for (const Mesh& m : {cube(), grid(5), twisted_grid()}) {
    const CatmullClarkPatch cc(m.v, m.f);
    const auto faces = cc.face_patches();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      auto uv = test::random_domain_points(20, 60 + unsigned(f));
      uv.push_back({0.5, 0}), uv.push_back({1, 0.25});
      const std::vector<Vec2> corners = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      uv.insert(uv.end(), corners.begin(), corners.end());
      const auto ref = osd_limit(m, int(f), uv);
      for (std::size_t i = 0; i < uv.size(); ++i) {
        const SurfaceJet a = faces[f]->evaluate(uv[i]);
        if (i + corners.size() < uv.size()) {
          interior = std::max(interior, jet_diff(a, ref[i]));
        } else {
          corner_d01 = std::max({corner_d01, max_abs(a.p - ref[i].p), max_abs(a.su - ref[i].su),
                                 max_abs(a.sv - ref[i].sv)});
          corner_d2 = std::max(corner_d2, jet_diff(a, ref[i]));
        }
      }
    }
  }
  std::printf(
      "figure catmull_clark_vs_osd_limit_stencils_jet %.3e\n"
      "figure catmull_clark_vs_osd_corner_position_first_derivatives %.3e\n"
      "figure catmull_clark_vs_osd_corner_second_derivatives %.3e\n",
      interior, corner_d01, corner_d2);
  EXPECT_LT(interior, 1e-11);
  EXPECT_LT(corner_d01, 1e-11);
}

TEST(ClassicCatmullClark, RegularFaceIsTheUniformBicubicBSpline) {
  const Mesh m = grid(5);
  const CatmullClarkPatch cc(m.v, m.f);
  const auto faces = cc.face_patches();
  // Face (2, 2) is regular: its limit is the uniform cubic B-spline on the 4x4 vertices around it.
  const int i0 = 1, j0 = 1, face = 2 * 5 + 2;
  std::vector<Vec3> pts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) pts.push_back(m.v[(i0 + i) * 6 + j0 + j]);
  const BSplinePatch b(3, 3, {-3, -2, -1, 0, 1, 2, 3, 4}, {-3, -2, -1, 0, 1, 2, 3, 4}, 4, 4, pts);
  double worst = 0;
  for (const Vec2& x : test::random_domain_points(200, 70))
    worst = std::max(worst, jet_diff(faces[face]->evaluate(x), b.evaluate(x)));
  std::printf("figure catmull_clark_regular_vs_bspline %.3e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

struct V {
  Vec3 p{0};
  void Clear(void* = nullptr) { p = Vec3(0); }
  void AddWithWeight(const V& s, double w) { p += w * s.p; }
};

TEST(ClassicCatmullClark, UniformRefinementConvergesToTheLimit) {
  for (const Mesh& m : {cube(), twisted_grid()}) {
    const CatmullClarkPatch cc(m.v, m.f);
    const auto faces = cc.face_patches();
    auto r = refiner_for(m);
    const int L = 7;
    r->RefineUniform(Far::TopologyRefiner::UniformOptions(L));
    Far::PrimvarRefinerReal<double> pr(*r);
    std::vector<std::vector<V>> lv(L + 1);
    for (const Vec3& p : m.v) lv[0].push_back({p});
    for (int l = 1; l <= L; ++l) {
      lv[l].resize(r->GetLevel(l).GetNumVertices());
      pr.Interpolate(l, lv[l - 1], lv[l]);
    }
    // Track a base corner (face 0's first vertex, u = v = 0) and face 0's centre (0.5, 0.5).
    int corner = m.f[0][0], centre = r->GetLevel(0).GetFaceChildVertex(0);
    const Vec3 lim_corner = faces[0]->evaluate({0, 0}).p,
               lim_centre = faces[0]->evaluate({0.5, 0.5}).p;
    double prev = 1e300;
    for (int l = 1; l <= L; ++l) {
      corner = r->GetLevel(l - 1).GetVertexChildVertex(corner);
      if (l > 1) centre = r->GetLevel(l - 1).GetVertexChildVertex(centre);
      const double d = std::max(glm::length(lv[l][corner].p - lim_corner),
                                glm::length(lv[l][centre].p - lim_centre));
      std::printf("figure catmull_clark_refinement_distance_level_%d %.3e\n", l, d);
      EXPECT_LT(d, prev / 3) << "level " << l;  // O(4^-l) convergence
      prev = d;
    }
    EXPECT_LT(prev, 1e-4);
  }
}

TEST(ClassicCatmullClark, FiniteEverywhereAndDerivativesMatchFiniteDifferences) {
  const Mesh m = cube();
  const CatmullClarkPatch cc(m.v, m.f);
  TessellationCache cache;
  double fd = 0;
  for (auto& f : cc.face_patches()) {
    PatchEvaluator ev(f->clone(), cache.get(f->domain(), 32));
    for (std::size_t i = 0; i < ev.sample_count(); ++i) {
      const auto& g = ev.geometry()[i];
      ASSERT_TRUE(std::isfinite(g.gaussian) && std::isfinite(g.mean) && std::isfinite(g.normal.x));
      ASSERT_EQ(g.status, GeometryStatus::Regular)
          << "sample " << i;  // tangent plane exists at EVs
    }
    for (const Vec2& x : test::random_domain_points(20, 71, 0.05, 0.95))
      fd = std::max(fd, test::fd_mismatch(*f, x, 1e-6));
  }
  std::printf("figure catmull_clark_fd %.3e\n", fd);
  EXPECT_LT(fd, 1e-5);
  const auto faces = cc.face_patches();
  EXPECT_LT(test::interface_mismatch(*faces[0], test::random_domain_points(5, 72)), 1e-12);
  EXPECT_LT(test::interface_mismatch(cc, test::random_domain_points(5, 73)), 1e-11);
}

double mesh_size(const Mesh& m) {
  Vec3 lo = m.v[0], hi = m.v[0];
  for (const Vec3& p : m.v) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

double angle_between_deg(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / M_PI;
}

TEST(ClassicCatmullClark, SurfacePiecesAreTheFacesOfTheAtlasAndOfOpenSubdiv) {
  double vs_osd = 0, vs_atlas = 0, side_vs_eval = 0, side_vs_osd = 0;
  for (const Mesh& m : {cube(), grid(5), twisted_grid()}) {
    const CatmullClarkPatch cc(m.v, m.f);
    const auto pieces = cc.surface_pieces();
    ASSERT_EQ(pieces.size(), m.f.size());
    const double F = double(m.f.size()), size = mesh_size(m);
    for (std::size_t f = 0; f < pieces.size(); ++f) {
      const Patch& piece = *pieces[f];
      ASSERT_EQ(piece.control_points(), cc.control_points());  // same vertices, same order
      ASSERT_EQ(piece.domain().side_count(), 4);
      const auto uv = test::random_domain_points(12, 80 + unsigned(f));
      const auto ref = osd_limit(m, int(f), uv);
      for (std::size_t i = 0; i < uv.size(); ++i) {
        const SurfaceJet a = piece.evaluate(uv[i]);
        vs_osd = std::max(vs_osd, jet_diff(a, ref[i]) / size);
        // The atlas strip of face f, its u derivatives rescaled to the face's own u.
        SurfaceJet b = cc.evaluate({(double(f) + uv[i].x) / F, uv[i].y});
        b.su /= F, b.suu /= F * F, b.suv /= F;
        vs_atlas = std::max(vs_atlas, jet_diff(a, b) / size);
      }
      // boundary_point (the patch's basis times its points' stencils over the base vertices)
      // against the piece's own evaluation (its cached patch points) and against OpenSubdiv's
      // own limit stencils (LimitStencilTableFactory, limit_point).
      for (int side = 0; side < 4; ++side)
        for (double t : {0.0, 0.3, 0.5, 0.91, 1.0}) {
          const Vec2 x = piece.domain().side_point(side, t);
          const Vec3 b = piece.boundary_point(side, t);
          side_vs_eval = std::max(side_vs_eval, max_abs(b - piece.evaluate(x).p) / size);
          side_vs_osd =
              std::max(side_vs_osd, max_abs(b - cc.limit().limit_point(int(f), x, m.v)) / size);
        }
    }
  }
  std::printf(
      "figure catmull_clark_pieces_vs_osd_limit_stencils_relative %.3e\n"
      "figure catmull_clark_pieces_vs_atlas_relative %.3e\n"
      "figure catmull_clark_boundary_point_vs_evaluate_relative %.3e\n"
      "figure catmull_clark_boundary_point_vs_osd_limit_stencils_relative %.3e\n",
      vs_osd, vs_atlas, side_vs_eval, side_vs_osd);
  EXPECT_LT(vs_osd, 1e-12);
  EXPECT_LT(vs_atlas, 1e-12);
  EXPECT_LT(side_vs_eval, 1e-12);
  EXPECT_LT(side_vs_osd, 1e-12);
}

TEST(ClassicCatmullClark, AdjacentPiecesShareTheirEdgesWithOneNormal) {
  // Face side i runs loop[i] -> loop[i+1] (u along v0 -> v1, v along v0 -> v3); the neighbour's
  // side over the same edge runs the other way, so side parameter t meets 1 - t.
  double gap = 0, angle = 0, angle_at_ev = 0;
  int edges = 0;
  for (const Mesh& m : {cube(), grid(5), twisted_grid()}) {
    const CatmullClarkPatch cc(m.v, m.f);
    const auto pieces = cc.surface_pieces();
    const double size = mesh_size(m);
    std::vector<int> valence(m.v.size(), 0);
    for (const auto& f : m.f)
      for (int v : f) ++valence[v];
    for (std::size_t f = 0; f < m.f.size(); ++f)
      for (std::size_t g = f + 1; g < m.f.size(); ++g)
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            const int a = m.f[f][i], b = m.f[f][(i + 1) % 4];
            if (m.f[g][j] != b || m.f[g][(j + 1) % 4] != a) continue;
            ++edges;
            for (int k = 0; k <= 32; ++k) {
              const double t = k / 32.0;
              const SurfaceJet p = pieces[f]->evaluate(pieces[f]->domain().side_point(i, t));
              const SurfaceJet q = pieces[g]->evaluate(pieces[g]->domain().side_point(j, 1 - t));
              gap = std::max(gap, glm::length(p.p - q.p) / size);
              const double ang = angle_between_deg(glm::cross(p.su, p.sv), glm::cross(q.su, q.sv));
              // End points on an interior extraordinary vertex: the Gregory end caps' limit
              // normal, reported separately.
              const int end = k == 0 ? a : k == 32 ? b : -1;
              const bool ev = end >= 0 && valence[end] != 4 && valence[end] > 2;
              (ev ? angle_at_ev : angle) = std::max(ev ? angle_at_ev : angle, ang);
            }
          }
  }
  std::printf(
      "figure catmull_clark_shared_edges %d\n"
      "figure catmull_clark_shared_edge_gap_relative %.3e\n"
      "figure catmull_clark_shared_edge_normal_angle_deg %.3e\n"
      "figure catmull_clark_shared_edge_normal_angle_at_extraordinary_deg %.3e\n",
      edges, gap, angle, angle_at_ev);
  EXPECT_EQ(edges, 12 + 2 * 5 * 4 + 2 * 4 * 3);  // cube, 5x5 grid, 4x4 grid
  EXPECT_LT(gap, 1e-12);
  EXPECT_LT(angle, 1e-6);
}

TEST(ClassicCatmullClark, SceneHasOneFullDensitySurfacePerFaceAndSyncFollowsADrag) {
  Mesh m = grid(6);
  for (auto& p : m.v) p.z += 0.1 * p.x * p.y;
  Scene scene;
  scene.patches.push_back({"cc", std::make_shared<CatmullClarkPatch>(m.v, m.f)});
  const int density = 10;
  TessellationCache cache;
  const SceneSurfaces ss = evaluate_scene(scene, density, std::nullopt, cache, "test");
  ASSERT_EQ(ss.surfaces.size(), m.f.size());
  const std::size_t full = cache.get(UnitSquareDomain(), density)->points.size();
  for (const SceneSurface& s : ss.surfaces) {
    EXPECT_EQ(s.patch, 0);
    EXPECT_EQ(s.evaluator->sample_count(), full);  // (density + 1)^2, not density / F across
  }

  SceneEvaluation live(scene, density, std::nullopt);
  std::vector<std::vector<SurfaceJet>> before;
  for (const SceneSurface& s : live.surfaces().surfaces) before.push_back(s.evaluator->jets());
  const int moved = 3 * 7 + 3;  // the middle vertex of the 6x6 grid: valence 4
  auto edited = std::shared_ptr<Patch>(scene.patches[0].patch->clone());
  edited->set_control_point(moved, m.v[moved] + Vec3(0.3, -0.2, 0.5));
  scene.patches[0].patch = edited;
  const SyncStats st = live.sync(scene);
  EXPECT_EQ(st.rebuilt_surfaces, 0u);
  const SceneEvaluation fresh(scene, density, std::nullopt);
  ASSERT_EQ(fresh.surfaces().surfaces.size(), live.surfaces().surfaces.size());
  const double size = mesh_size(m);
  double worst = 0;
  std::size_t touched = 0, expected_touched = 0;
  for (std::size_t f = 0; f < m.f.size(); ++f) {
    const auto& a = live.surfaces().surfaces[f].evaluator->jets();
    const auto& b = fresh.surfaces().surfaces[f].evaluator->jets();
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, jet_diff(a[i], b[i]) / size);
    // The vertex's support: the faces sharing a vertex with a face around it (the 1-ring of
    // faces of the faces that contain it).
    bool near = false;
    for (const auto& g : m.f)
      if (std::count(g.begin(), g.end(), moved))
        for (int v : g) near = near || std::count(m.f[f].begin(), m.f[f].end(), v) > 0;
    expected_touched += near;
    bool changed = false;
    for (std::size_t i = 0; i < a.size(); ++i) changed = changed || !(a[i].p == before[f][i].p);
    touched += changed;
    if (!near) {
      EXPECT_FALSE(changed) << "face " << f << " is outside the vertex's support";
    }
  }
  std::printf(
      "figure catmull_clark_sync_vs_fresh_relative %.3e\n"
      "figure catmull_clark_sync_faces_changed %zu of %zu (support %zu)\n",
      worst, touched, m.f.size(), expected_touched);
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(touched, 16u);  // a regular vertex's bicubic B-spline support: 4x4 faces
  EXPECT_EQ(touched, expected_touched);
}

Mesh mixed() {  // a 3x3 grid with a quad split into two triangles and two quads made a hexagon
  Mesh m = grid(3);
  for (auto& p : m.v) p.z += 0.1 * p.x * p.y;
  std::vector<std::vector<int>> f = {{0, 4, 5}, {0, 5, 1}, {5, 9, 10, 11, 7, 6}};
  for (int k : {1, 2, 3, 6, 7, 8}) f.push_back(m.f[k]);
  m.f = f;
  return m;
}

TEST(ClassicCatmullClark, TrianglesAndNGonsAreQuadrangulatedPtexFaces) {
  const Mesh m = mixed();
  const CatmullClarkPatch cc(m.v, m.f);
  const auto pieces = cc.surface_pieces();
  ASSERT_EQ(pieces.size(), 3u + 3u + 6u + 6u);  // n sub-faces per n-gon, one per quad
  const double size = mesh_size(m);
  double vs_osd = 0, fd = 0;
  TessellationCache cache;
  for (std::size_t f = 0; f < pieces.size(); ++f) {
    auto uv = test::random_domain_points(12, 90 + unsigned(f));
    uv.push_back({0, 0}), uv.push_back({1, 0.5}), uv.push_back({0.5, 1});
    const auto ref = osd_limit(m, int(f), uv);
    for (std::size_t i = 0; i < uv.size(); ++i) {
      const SurfaceJet a = pieces[f]->evaluate(uv[i]);
      // Positions: OpenSubdiv's limit stencils carry the same 2x derivative scale of non-quad
      // sub-faces that CatmullClarkLimit::basis corrects, so derivatives are checked against
      // finite differences below instead.
      const double d = max_abs(a.p - ref[i].p);
      vs_osd = std::max(vs_osd, d / size);
    }
    PatchEvaluator ev(pieces[f], cache.get(pieces[f]->domain(), 16));
    for (std::size_t i = 0; i < ev.sample_count(); ++i) {
      const auto& g = ev.geometry()[i];
      ASSERT_TRUE(std::isfinite(g.gaussian) && std::isfinite(g.mean)) << "piece " << f;
      ASSERT_EQ(g.status, GeometryStatus::Regular) << "piece " << f << " sample " << i;
    }
    for (const Vec2& x : test::random_domain_points(5, 95, 0.05, 0.95))
      fd = std::max(fd, test::fd_mismatch(*pieces[f], x, 1e-6));
  }
  // OpenSubdiv's sub-face k of an n-gon runs from corner k (0, 0) to the face centre (1, 1):
  // all six sub-faces of the hexagon meet there.
  double centre = 0;
  const Vec3 c = pieces[6]->evaluate({1, 1}).p;
  for (int k = 7; k < 12; ++k)
    centre = std::max(centre, glm::length(pieces[k]->evaluate({1, 1}).p - c) / size);
  std::printf(
      "figure catmull_clark_ngon_pieces_vs_osd_relative %.3e\n"
      "figure catmull_clark_ngon_fd %.3e\n"
      "figure catmull_clark_hexagon_centre_spread_relative %.3e\n",
      vs_osd, fd, centre);
  EXPECT_LT(vs_osd, 1e-12);
  EXPECT_LT(fd, 1e-5);
  EXPECT_LT(centre, 1e-12);
}

TEST(ClassicCatmullClark, BadMeshesAreRejected) {
  Mesh m = cube();
  m.f[0] = {0, 2};  // not a polygon
  EXPECT_THROW(CatmullClarkPatch(m.v, m.f), std::invalid_argument);
  m = cube();
  m.f[1] = {4, 6, 7, 5};  // flipped orientation
  EXPECT_THROW(CatmullClarkPatch(m.v, m.f), std::invalid_argument);
  m = cube();
  m.f[2] = {0, 1, 5, 99};
  EXPECT_THROW(CatmullClarkPatch(m.v, m.f), std::invalid_argument);
}

}  // namespace
}  // namespace pl
