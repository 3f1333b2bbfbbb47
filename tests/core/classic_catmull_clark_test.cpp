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
  std::vector<int> counts(m.f.size(), 4), idx;
  for (const auto& f : m.f) idx.insert(idx.end(), f.begin(), f.end());
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

TEST(ClassicCatmullClark, BadMeshesAreRejected) {
  Mesh m = cube();
  m.f[0] = {0, 2, 3};  // a triangle
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
