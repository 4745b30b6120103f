// The mesh error of a confirmed root's growth rate (rom/confirm/mesh_error.hpp) on sequences whose limit is known:
// g(h) = g* + c h^p on levels h, h/2, h/4, ...; the estimate must cover the finest level's true error, Richardson's
// extrapolation must land on g* for an exact power law, and a sequence that does not converge must not be called
// converged.
#include "mesh_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

namespace {
using rc::rom::mesh_error;
using cd = std::complex<double>;

// sigma on `levels` levels of g(h) = limit + c h^p (growth -Im sigma), frequency 0.5.
std::vector<cd> power_law(double limit, double c, double p, int levels) {
  std::vector<cd> out;
  for (int l = 0; l < levels; ++l) out.push_back({0.5, -(limit + c * std::pow(0.5, p * l))});
  return out;
}

TEST(MeshError, TwoLevelsBoundTheFinestErrorAtFirstOrderOrMore) {
  for (double p : {1.0, 2.0, 4.0}) {
    const auto e = mesh_error(power_law(-3e-4, 2e-4, p, 2), 0.02, 0);
    const double truth = std::abs(e.growth - -3e-4);
    EXPECT_GE(e.error, truth * (1 - 1e-12)) << "order " << p;
    EXPECT_EQ(e.order, 0);  // two levels measure no order
  }
}

// The 3-D mesh check's levels (general_mesh_check.hpp): a mesh 1.5 times as coarse, then the table's. Two levels at
// ratio 1.5 give |d| / 0.5: the finest level's true error at first order exactly, more at any higher order; three
// levels at that ratio measure the order and extrapolate to the limit as halving does.
TEST(MeshError, LevelsAtRatioOneAndAHalf) {
  const auto levels = [](double p, int n) {
    std::vector<cd> out;
    for (int l = 0; l < n; ++l) out.push_back({0.5, -(-3e-4 + 1e-4 * std::pow(1.5, -p * l))});
    return out;
  };
  for (double p : {1.0, 2.0, 4.0}) {
    const auto e = mesh_error(levels(p, 2), 0.02, 0, true, 1.5);
    const double truth = std::abs(e.growth - -3e-4);
    EXPECT_GE(e.error, truth * (1 - 1e-12)) << "order " << p;
    if (p == 1.0) {
      EXPECT_NEAR(e.error, truth, 1e-12 * truth);
    }
    const auto e3 = mesh_error(levels(p, 3), 0.02, 0, true, 1.5);
    EXPECT_NEAR(e3.order, p, 1e-8);
    EXPECT_NEAR(e3.extrapolated, -3e-4, 1e-15);
  }
}

TEST(MeshError, ThreeLevelsGiveTheOrderAndRichardsonsLimit) {
  for (double p : {1.0, 2.0, 3.0}) {
    const auto e = mesh_error(power_law(-3e-4, 1e-4, p, 3), 0.02, 0);
    EXPECT_NEAR(e.order, p, 1e-9);
    EXPECT_NEAR(e.extrapolated, -3e-4, 1e-15);
    const double truth = std::abs(e.growth - -3e-4);
    EXPECT_GE(e.error, truth);                 // the grid convergence index covers the true error
    EXPECT_LE(e.error, 1.25 * truth * (1 + 1e-9));  // and by no more than its safety factor
    EXPECT_TRUE(e.asymptotic);
  }
}

TEST(MeshError, LevelsInTheOrderTakeNoPowerLaw) {
  // p-refinement: 2.97e-4 approached as 3.84e-3, 2.968e-4, 2.970e-4 (no power of h): the error is the larger of the
  // last two differences, never an extrapolation.
  const std::vector<cd> levels = {{-7.8, 3.84e-3}, {-7.8, 2.968e-4}, {-7.8, 2.970e-4}};
  const auto e = mesh_error(levels, 0.02, 0, false);
  EXPECT_EQ(e.order, 0);
  EXPECT_FALSE(e.asymptotic);
  EXPECT_NEAR(e.error, 3.84e-3 - 2.968e-4, 1e-15);
  EXPECT_FALSE(e.converged);
  const auto two = mesh_error({levels[1], levels[2]}, 0.02, 0, false);
  EXPECT_NEAR(two.error, 2e-7, 1e-15);
  EXPECT_TRUE(two.converged);
}

TEST(MeshError, ConvergedOnlyWithinTheTolerance) {
  // 1 % moves: converged at 2 %, not at 0.5 %.
  const std::vector<cd> levels = {{0.5, 1.01e-3}, {0.5, 1.0e-3}};
  EXPECT_TRUE(mesh_error(levels, 0.02, 0).converged);
  EXPECT_FALSE(mesh_error(levels, 0.005, 0).converged);
  EXPECT_NEAR(mesh_error(levels, 0.02, 0).relative(), 0.01, 1e-12);
  EXPECT_LT(mesh_error(levels, 0.02, 0).growth, 0);  // Im sigma > 0: a decay
}

TEST(MeshError, ASequenceThatDoesNotFallIsNeitherAsymptoticNorConverged) {
  // The 60 % sphere at Ek 9e-7: decay 8.92e-3, 7.17e-3, 5.09e-3 on P6 meshes h, h/2, h/4 (the limit is
  // 2.97e-4): the differences grow, so no order is taken and the error is the larger difference.
  const std::vector<cd> levels = {{-0.24, 8.92e-3}, {-0.24, 7.17e-3}, {-0.24, 5.09e-3}};
  const auto e = mesh_error(levels, 0.02, 0);
  EXPECT_FALSE(e.asymptotic);
  EXPECT_FALSE(e.converged);
  EXPECT_NEAR(e.error, 2.08e-3, 1e-12);
  EXPECT_TRUE(e.sign_settled);
}

TEST(MeshError, AGrowthWithinItsErrorHasNoSettledSign) {
  const std::vector<cd> levels = {{1.0, 2e-5}, {1.0, -1e-5}};  // decay on the coarse mesh, growth on the fine one
  const auto e = mesh_error(levels, 0.02, 0);
  EXPECT_GT(e.growth, 0);
  EXPECT_FALSE(e.sign_settled);
  EXPECT_FALSE(e.converged);
}

}  // namespace
