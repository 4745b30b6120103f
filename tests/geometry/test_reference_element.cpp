// The reference rules come from gmsh; check they are what the header promises.
#include "meridian_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using rc::geometry::reference_edge;
using rc::geometry::reference_triangle;

// Exact ∫∫ u^i v^j over the reference triangle: i! j! / (i + j + 2)!.
double triangle_moment(int i, int j) {
  return std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3);
}

TEST(ReferenceTriangle, IntegratesPolynomialsOfItsDegreeExactly) {
  for (int degree : {1, 2, 4, 7, 8, 9, 12, 18, 20, 30}) {
    const auto ref = reference_triangle(1, degree);
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j) {
        double sum = 0;
        for (std::size_t q = 0; q < ref.weights.size(); ++q)
          sum += ref.weights[q] * std::pow(ref.points[q][0], i) * std::pow(ref.points[q][1], j);
        EXPECT_NEAR(sum, triangle_moment(i, j), 1e-14) << "degree " << degree << " u^" << i << " v^" << j;
      }
  }
}

// gmsh's own rules of degree 9..20 put points outside the triangle (r < 0 near the axis); ours
// must not, at any degree.
TEST(ReferenceTriangle, PointsInsideAndWeightsPositiveAboveDegreeEight) {
  for (int degree = 9; degree <= 30; ++degree) {
    const auto ref = reference_triangle(2, degree);
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      const auto [u, v] = ref.points[q];
      EXPECT_GT(ref.weights[q], 0.0) << "degree " << degree;
      EXPECT_TRUE(u > 0 && v > 0 && u + v < 1) << "degree " << degree << ": (" << u << ", " << v << ")";
    }
  }
}

TEST(ReferenceEdge, IntegratesPolynomialsOfItsDegreeExactly) {
  for (int degree : {0, 1, 3, 6, 11, 18, 30}) {
    const auto ref = reference_edge(2, degree);
    for (int i = 0; i <= degree; ++i) {
      double sum = 0;
      for (std::size_t q = 0; q < ref.weights.size(); ++q) sum += ref.weights[q] * std::pow(ref.points[q], i);
      EXPECT_NEAR(sum, 1.0 / (i + 1), 1e-14) << "degree " << degree << " s^" << i;
    }
  }
}

// Lagrange bases reproduce linear functions: with nodes at gmsh's local positions, Σ N_a x_a = x.
// Here we only need partition of unity and a vanishing gradient sum, which hold for any order.
TEST(ReferenceTriangle, BasisIsAPartitionOfUnity) {
  for (int order = 1; order <= 6; ++order) {
    const auto ref = reference_triangle(order, 2 * order);
    ASSERT_EQ(ref.nodes_per_element, (order + 1) * (order + 2) / 2);
    ASSERT_EQ(ref.N.size(), ref.weights.size() * ref.nodes_per_element);
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      double s = 0, su = 0, sv = 0;
      for (int a = 0; a < ref.nodes_per_element; ++a) {
        s += ref.N[q * ref.nodes_per_element + a];
        su += ref.dN[(q * ref.nodes_per_element + a) * 2];
        sv += ref.dN[(q * ref.nodes_per_element + a) * 2 + 1];
      }
      EXPECT_NEAR(s, 1.0, 1e-12);
      EXPECT_NEAR(su, 0.0, 1e-10);
      EXPECT_NEAR(sv, 0.0, 1e-10);
    }
  }
}

// Edge basis in gmsh line order: N_0 is 1 at s = 0 and N_1 at s = 1, then interior nodes from
// s = 0 to 1; d/ds is on [0, 1] (twice gmsh's d/dxi).
TEST(ReferenceEdge, NodeOrderAndDerivativesAreOnTheUnitInterval) {
  for (int order = 1; order <= 6; ++order) {
    const auto ref = reference_edge(order, 2 * order);
    const int n = order + 1;
    double wsum = 0;
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      wsum += ref.weights[q];
      // Nodal coordinates s_a: 0, 1, then k/order. Σ N_a s_a = s and Σ dN_a s_a = 1.
      double s = 0, ds = 0;
      for (int a = 0; a < n; ++a) {
        const double sa = a == 0 ? 0.0 : a == 1 ? 1.0 : double(a - 1) / order;
        s += ref.N[q * n + a] * sa;
        ds += ref.dN[q * n + a] * sa;
      }
      EXPECT_NEAR(s, ref.points[q], 1e-12) << "order " << order;
      EXPECT_NEAR(ds, 1.0, 1e-10) << "order " << order;
    }
    EXPECT_NEAR(wsum, 1.0, 1e-14);
  }
}

TEST(ReferenceTriangle, CallableRepeatedly) {
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(reference_triangle(3, 6).nodes_per_element, 10);
    EXPECT_EQ(reference_edge(3, 6).order, 3);
  }
}

TEST(ReferenceTriangle, RejectsBadArguments) {
  EXPECT_THROW(reference_triangle(0, 2), std::runtime_error);
  EXPECT_THROW(reference_triangle(7, 2), std::runtime_error);
  EXPECT_THROW(reference_triangle(2, -1), std::runtime_error);
  EXPECT_THROW(reference_triangle(2, 31), std::runtime_error);  // gmsh would crash
  EXPECT_THROW(reference_edge(2, 31), std::runtime_error);
  EXPECT_THROW(reference_edge(0, 2), std::runtime_error);
}

}  // namespace
