// count_linear_tets (geometry/linear_tet_counts.hpp) against counts by hand: one tetrahedron, whose order-p node count
// is the simplex's (p+1)(p+2)(p+3)/6 and all on its wall, and two sharing a face, whose shared face is not wall.
#include "linear_tet_counts.hpp"

#include <gtest/gtest.h>

using rc::geometry::count_linear_tets;

TEST(LinearTetCounts, OneTetrahedronHasTheSimplexsNodes) {
  const auto c = count_linear_tets({{7, 3, 9, 1}});
  EXPECT_EQ(c.vertices, 4u);
  EXPECT_EQ(c.edges, 6u);
  EXPECT_EQ(c.faces, 4u);
  EXPECT_EQ(c.wall_faces, 4u);
  for (int p = 1; p <= 6; ++p) {
    EXPECT_EQ(c.nodes(p), static_cast<std::size_t>((p + 1) * (p + 2) * (p + 3) / 6)) << p;
    EXPECT_EQ(c.nodes(p) - c.wall_nodes(p), static_cast<std::size_t>((p - 1) * (p - 2) * (p - 3) / 6)) << p;
  }
}

TEST(LinearTetCounts, TwoTetrahedraShareOneFaceOffTheWall) {
  const auto c = count_linear_tets({{0, 1, 2, 3}, {4, 2, 1, 0}});
  EXPECT_EQ(c.vertices, 5u);
  EXPECT_EQ(c.edges, 9u);
  EXPECT_EQ(c.faces, 7u);
  EXPECT_EQ(c.wall_faces, 6u);
  EXPECT_EQ(c.wall_edges, 9u);
  EXPECT_EQ(c.wall_vertices, 5u);
  // P3: 5 + 2·9 + 7 = 30 nodes; inside: the shared face's centre only.
  EXPECT_EQ(c.nodes(3), 30u);
  EXPECT_EQ(c.nodes(3) - c.wall_nodes(3), 1u);
}
