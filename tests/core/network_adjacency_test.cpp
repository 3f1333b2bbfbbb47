// The network's one adjacency (core/scene/network.hpp): EdgeIndex finds the edge joining two
// vertices whichever way round, and edge_uses lists the face sides using each edge. On a valid
// network edge_uses agrees with the topology validate_network builds while checking the rules,
// counted here by brute force over every face side and every edge.
#include <gtest/gtest.h>

#include "core/scene/network.hpp"
#include "network_test_util.hpp"

namespace pl {
namespace {

TEST(NetworkAdjacency, EdgeIndexFindsEachEdgeBothWaysAndNothingElse) {
  const Network n = test::sphere_blob(true);
  const EdgeIndex index(n);
  const int nv = int(n.vertices.size());
  for (int a = 0; a < nv; ++a)
    for (int b = 0; b < nv; ++b) {
      int expected = -1;  // brute force: the edge with ends {a, b}
      for (std::size_t e = 0; e < n.edges.size(); ++e)
        if ((n.edges[e].v[0] == a && n.edges[e].v[1] == b) ||
            (n.edges[e].v[0] == b && n.edges[e].v[1] == a))
          expected = int(e);
      EXPECT_EQ(index.find(a, b), expected) << a << " " << b;
    }
}

TEST(NetworkAdjacency, AddKeepsTheFirstEdgeOfAPair) {
  EdgeIndex index;
  EXPECT_EQ(index.add(3, 7, 0), 0);
  EXPECT_EQ(index.add(7, 3, 1), 0);  // the pair is already joined by edge 0
  EXPECT_EQ(index.add(7, 4, 2), 2);
  EXPECT_EQ(index.find(3, 7), 0);
  EXPECT_EQ(index.find(4, 7), 2);
  EXPECT_EQ(index.find(3, 4), -1);
}

TEST(NetworkAdjacency, EdgeUsesAgreeWithTheValidatedTopology) {
  for (bool closed : {false, true}) {
    const Network n = test::sphere_blob(closed);
    const NetworkTopology topo = validate_network(n, "blob");
    const auto uses = edge_uses(n, EdgeIndex(n));
    ASSERT_EQ(uses.size(), topo.edge_faces.size());
    std::size_t total = 0;
    for (std::size_t e = 0; e < uses.size(); ++e) {
      ASSERT_EQ(uses[e].size(), topo.edge_faces[e].size()) << "edge " << e;
      for (std::size_t k = 0; k < uses[e].size(); ++k) {
        EXPECT_EQ(uses[e][k].face, topo.edge_faces[e][k].face);
        EXPECT_EQ(uses[e][k].side, topo.edge_faces[e][k].side);
        // The side runs between the edge's two vertices.
        const auto& loop = n.faces[uses[e][k].face].loop;
        const int a = loop[uses[e][k].side], b = loop[(uses[e][k].side + 1) % loop.size()];
        EXPECT_EQ(std::minmax(a, b), std::minmax(n.edges[e].v[0], n.edges[e].v[1]));
      }
      total += uses[e].size();
    }
    std::size_t sides = 0;
    for (const NetworkFace& f : n.faces) sides += f.loop.size();
    EXPECT_EQ(total, sides);  // every face side uses exactly one edge
  }
}

}  // namespace
}  // namespace pl
