#include "core/network/network_filling.hpp"

#include <gtest/gtest.h>

#include "core/base/data_error.hpp"
#include "core/network/face_ribbons.hpp"
#include "gregory_test_util.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

struct Filled {
  Network net;
  NetworkTopology topo;
  NetworkFilling filling;
};
Filled fill(Network n) {
  Filled f{std::move(n), {}, {}};
  f.topo = validate_network(f.net, "test");
  f.filling = fill_network(f.net, f.topo, std::nullopt, "test");
  return f;
}

// Boundary, G1 and finiteness of one network, measured from exact derivatives.
void expect_g1_filling(const Network& n, const char* what) {
  const Filled f = fill(n);
  const auto faces = test::surfaces(f.filling);
  const double size = test::network_size(f.net);
  const double dev = test::max_boundary_deviation(f.net, f.topo, faces);
  const double angle = test::max_g1_angle_deg(f.topo, faces);
  std::printf("figure %s_max_boundary_deviation_rel %.3g\nfigure %s_max_g1_angle_deg %.3g\n", what,
              dev / size, what, angle);
  EXPECT_LT(dev / size, 1e-12) << what;
  EXPECT_LT(angle, 1e-6) << what;
  EXPECT_TRUE(f.filling.projected_vertices.empty()) << what;
  for (const FacePatch& fp : f.filling.faces) {
    EXPECT_EQ(fp.patch->type(), n.faces[fp.face].loop.size() == 3 ? "gregory-tri" : "gregory-quad");
    for (Vec2 x : fp.patch->domain().tessellate(12).points)
      ASSERT_TRUE(test::finite_jet(fp.patch->evaluate(x))) << what << " face " << fp.face;
  }
}

TEST(NetworkFilling, ClosedSphereBlobIsG1WithValence345) {
  expect_g1_filling(test::sphere_blob(true), "closed_sphere_blob");
}

TEST(NetworkFilling, OpenSphereBlobIsG1) {
  expect_g1_filling(test::sphere_blob(false), "open_sphere_blob");
}

TEST(NetworkFilling, ClosedEllipsoidBlobIsG1) {
  const glm::dmat3 m(1.5, 0.2, 0.0, 0.0, 1.0, 0.3, 0.1, 0.0, 0.7);  // columns
  expect_g1_filling(test::mapped(test::sphere_blob(true), m), "closed_ellipsoid_blob");
}

TEST(NetworkFilling, CubeSphereIsClosedOutwardAndG1) {
  for (int k : {1, 3}) {
    const Network n = cube_sphere_network(k);
    ASSERT_EQ(n.faces.size(), 6u * k * k);
    ASSERT_EQ(n.edges.size(), 12u * k * k);
    ASSERT_EQ(n.vertices.size(), 6u * k * k + 2);
    const NetworkTopology topo = validate_network(n, "cube sphere");
    for (const auto& uses : topo.edge_faces) EXPECT_EQ(uses.size(), 2u);  // closed
    for (const Vec3& v : n.vertices) EXPECT_NEAR(glm::length(v), 1.0, 1e-15);
    // Outward: the loop's right-hand normal agrees with the position on the sphere.
    for (const NetworkFace& f : n.faces) {
      Vec3 area(0), centre(0);
      for (std::size_t i = 0; i < f.loop.size(); ++i) {
        const Vec3 a = n.vertices[f.loop[i]], b = n.vertices[f.loop[(i + 1) % f.loop.size()]];
        area += glm::cross(a, b);
        centre += a;
      }
      EXPECT_GT(glm::dot(area, centre), 0) << f.name;
    }
    expect_g1_filling(n, k == 1 ? "cube_sphere_24" : "cube_sphere_54");
  }
}

TEST(NetworkFilling, OpenHeightFieldWithGivenAndFittedNormalsIsG1) {
  expect_g1_filling(test::height_field(), "open_height_field");
}

TEST(NetworkFilling, NormalsPointToTheFacesOutwardSide) {
  const Filled f = fill(test::sphere_blob(true));
  for (const FacePatch& fp : f.filling.faces) {
    const Vec2 c = fp.patch->domain().interior_point();
    const SurfaceJet j = fp.patch->evaluate(c);
    EXPECT_GT(glm::dot(glm::cross(j.su, j.sv), j.p), 0) << "face " << fp.face;
  }
}

// At an edge used by one face, the cross-boundary tangents at the ends are the neighbouring
// edges' tangents (the patch corners), and the ribbon's end points are those edges' handles.
TEST(NetworkFilling, BoundaryEdgeRibbonsInterpolateTheNeighbouringEdgeTangents) {
  const Network n = test::sphere_blob(false);
  const NetworkTopology topo = validate_network(n, "test");
  std::vector<ProjectedVertex> projected;
  const auto ribbons = build_face_ribbons(n, topo, projected);
  int checked = 0;
  for (std::size_t f = 0; f < n.faces.size(); ++f) {
    const auto& loop = n.faces[f].loop;
    const int sides = int(loop.size());
    for (int i = 0; i < sides; ++i) {
      const CubicRibbon& r = ribbons[f].sides[i];
      const BezierCurve prev = n.edge_curve(topo.face_sides[f][(i + sides - 1) % sides].edge);
      const BezierCurve next = n.edge_curve(topo.face_sides[f][(i + 1) % sides].edge);
      // The handle of the previous side's edge next to loop[i], of the next side's next to
      // loop[i+1].
      const auto handle_at = [&](const BezierCurve& c, const Vec3& v) {
        return c.control_points()[0] == v ? c.control_points()[1] : c.control_points()[2];
      };
      EXPECT_EQ(r.inner[0], handle_at(prev, n.vertices[loop[i]]));
      EXPECT_EQ(r.inner[3], handle_at(next, n.vertices[loop[(i + 1) % sides]]));
      EXPECT_EQ(r.boundary[0], n.vertices[loop[i]]);
      EXPECT_EQ(r.boundary[3], n.vertices[loop[(i + 1) % sides]]);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 5 * 3 + 5 * 4);
}

// The CK field of every side lies in span(b(t), c(t)): checked independently as the
// cross-boundary vector being orthogonal to the normal n(t) = b(t) x c(t) of the edge's plane
// field, built here from the sphere's normals (the true tangent planes at the vertices).
TEST(NetworkFilling, RibbonCrossTangentsLieInTheInterpolatedPlanes) {
  const Network n = test::sphere_blob(true);
  const NetworkTopology topo = validate_network(n, "test");
  std::vector<ProjectedVertex> projected;
  const auto ribbons = build_face_ribbons(n, topo, projected);
  for (std::size_t f = 0; f < n.faces.size(); ++f)
    for (std::size_t i = 0; i < ribbons[f].sides.size(); ++i) {
      const CubicRibbon& r = ribbons[f].sides[i];
      const Vec3 n0 = glm::normalize(r.boundary[0]), n1 = glm::normalize(r.boundary[3]);
      std::vector<Vec3> bp(r.boundary.begin(), r.boundary.end());
      std::vector<Vec3> cross;
      for (int j = 0; j < 4; ++j) cross.push_back(3.0 * (r.inner[j] - r.boundary[j]));
      const BezierCurve edge(bp), d = edge.derivative(), a(cross);
      for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const Vec3 c = d.point(t);
        const Vec3 b = (1 - t) * glm::normalize(glm::cross(n0, d.point(0))) +
                       t * glm::normalize(glm::cross(n1, d.point(1)));
        const Vec3 normal = glm::normalize(glm::cross(c, b));
        EXPECT_LT(std::fabs(glm::dot(normal, a.point(t))), 1e-13) << f << " " << i << " " << t;
        EXPECT_GT(glm::dot(glm::cross(c, a.point(t)), edge.point(t)), 0);  // into the face
      }
    }
}

// A cube corner: three orthogonal edges at vertex 0 cannot share a plane; their least-squares
// fit is a tie, broken by the faces' corner normals: the plane at vertex 0 has normal
// -(1,1,1)/sqrt 3, which every edge there leaves by asin(1/sqrt 3) = 35.26 degrees.
TEST(NetworkFilling, NonCoplanarEndTangentsAreProjectedAndReported) {
  Network n;
  n.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  const auto line = [&](int a, int b) {
    const Vec3 p = n.vertices[a], q = n.vertices[b];
    n.edges.push_back({{a, b}, {p + (q - p) / 3.0, p + 2.0 * (q - p) / 3.0}, ""});
  };
  line(0, 1), line(0, 2), line(0, 3), line(1, 4), line(2, 4), line(2, 5), line(3, 5), line(1, 6),
      line(3, 6);
  n.faces = {{{0, 2, 4, 1}, FaceScheme::Auto, ""},
             {{0, 1, 6, 3}, FaceScheme::Auto, ""},
             {{0, 3, 5, 2}, FaceScheme::Auto, ""}};
  const Filled f = fill(n);
  // Vertices 1, 2, 3 are corners of two faces: their tie-broken planes are normal to the sum of
  // the two corner normals, e.g. -(0,1,1)/sqrt 2 at vertex 1, which its edges towards 4 and 6
  // leave by 45 degrees.
  ASSERT_EQ(f.filling.projected_vertices.size(), 4u);
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(f.filling.projected_vertices[v].vertex, v);
    EXPECT_NEAR(f.filling.projected_vertices[v].max_angle_deg,
                v == 0 ? std::asin(1 / std::sqrt(3.0)) * 180 / M_PI : 45.0, 1e-9);
  }
  const auto faces = test::surfaces(f.filling);
  EXPECT_LT(test::max_boundary_deviation(f.net, f.topo, faces), 1e-14);
  for (const FacePatch& fp : f.filling.faces)
    for (Vec2 x : fp.patch->domain().tessellate(8).points)
      EXPECT_TRUE(test::finite_jet(fp.patch->evaluate(x)));
}

// Gregory and GB faces are built from the same ribbons, so a face switched to GB still meets its
// Gregory neighbours G1 and interpolates its edges.
TEST(NetworkFilling, AGbFaceAmongGregoryFacesKeepsG1) {
  Network n = test::sphere_blob(true);
  n.faces[3].scheme = FaceScheme::GB;
  const Filled f = fill(n);
  EXPECT_NE(f.filling.faces[3].patch->type().rfind("gregory", 0), 0u);
  EXPECT_EQ(f.filling.faces[2].patch->type(), "gregory-tri");
  const auto faces = test::surfaces(f.filling);
  EXPECT_LT(test::max_boundary_deviation(f.net, f.topo, faces) / test::network_size(f.net), 1e-12);
  EXPECT_LT(test::max_g1_angle_deg(f.topo, faces), 1e-6);
}

TEST(NetworkFilling, DegenerateGeometryIsADataErrorNamingTheObject) {
  {  // a handle on its vertex: no end tangent
    Network n = test::sphere_blob(false);
    n.edges[4].handles[0] = n.vertices[n.edges[4].v[0]];
    const NetworkTopology topo = validate_network(n, "f");
    try {
      fill_network(n, topo, std::nullopt, "f");
      FAIL();
    } catch (const DataError& e) {
      EXPECT_EQ(e.where(), "network.edges[4].handles[0]");
      EXPECT_EQ(e.source(), "f");
    }
  }
  {  // collinear tangents at a valence-2 corner without a given normal
    Network n;
    n.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
    const auto line = [&](int a, int b) {
      const Vec3 p = n.vertices[a], q = n.vertices[b];
      n.edges.push_back({{a, b}, {p + (q - p) / 3.0, p + 2.0 * (q - p) / 3.0}, ""});
    };
    line(0, 1), line(1, 2), line(2, 3), line(3, 0);
    n.faces = {{{0, 1, 2, 3}, FaceScheme::Auto, ""}};
    const NetworkTopology topo = validate_network(n, "f");
    try {
      fill_network(n, topo, std::nullopt, "f");
      FAIL();
    } catch (const DataError& e) {
      EXPECT_EQ(e.where(), "network.vertices[1]");
    }
  }
}

}  // namespace
}  // namespace pl
