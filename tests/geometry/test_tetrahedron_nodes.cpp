// The reference tetrahedron's Lagrange nodes for nodal fields (geometry/tetrahedron_nodes.hpp): the sub-tetrahedra
// tile the element exactly (order³ of them, each of volume 1/(6 order³), positive), every lattice node is used, and
// the nodal gradients reproduce linear functions (Σ_a ∇N_a x_a = I at every node, Σ_a ∇N_a = 0).
#include "tetrahedron_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

double volume(const rc::geometry::TetrahedronNodes& t, const std::array<int, 4>& s) {
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) e[k][d] = t.points[s[k + 1]][d] - t.points[s[0]][d];
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
}

TEST(TetrahedronNodes, SubTetrahedraTileTheElement) {
  for (int p = 1; p <= 6; ++p) {
    const auto t = rc::geometry::tetrahedron_nodes(p);
    ASSERT_EQ(t.sub_tetrahedra.size(), static_cast<std::size_t>(p * p * p)) << "order " << p;
    std::set<int> used;
    for (const auto& s : t.sub_tetrahedra) {
      EXPECT_NEAR(volume(t, s), 1.0 / (6.0 * p * p * p), 1e-14) << "order " << p;
      used.insert(s.begin(), s.end());
    }
    EXPECT_EQ(used.size(), static_cast<std::size_t>(t.nodes_per_element)) << "order " << p;
  }
}

TEST(TetrahedronNodes, NodalGradientsReproduceLinearFunctions) {
  for (int p = 1; p <= 6; ++p) {
    const auto t = rc::geometry::tetrahedron_nodes(p);
    const int n = t.nodes_per_element;
    double worst = 0;
    for (int b = 0; b < n; ++b)
      for (int d = 0; d < 3; ++d) {
        double sum = 0, x[3] = {0, 0, 0};
        for (int a = 0; a < n; ++a) {
          const double g = t.dN[(b * n + a) * 3 + d];
          sum += g;
          for (int k = 0; k < 3; ++k) x[k] += g * t.points[a][k];
        }
        worst = std::max(worst, std::abs(sum));
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(x[k] - (k == d ? 1.0 : 0.0)));
      }
    EXPECT_LT(worst, 1e-9) << "order " << p;
  }
}

}  // namespace
