// The closed forms themselves (modes/ideal/closed_forms.hpp) against numbers published independently of them.
#include "closed_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace rc::modes;

TEST(ClosedForms, SpheroidWithEqualAxesIsTheSphere) {
  const auto s = exact::spheroid(1.0, 1.0);
  EXPECT_DOUBLE_EQ(s.mode.lambda, 1.0);
  EXPECT_NEAR(s.mode.E, 8 * std::numbers::pi / 15, 1e-15);
  EXPECT_NEAR(s.A_f, 8 * std::numbers::pi / 15, 1e-15);
  EXPECT_EQ(s.J_zh, 0.0);
}

TEST(ClosedForms, CylinderDominantModeMatchesSpecValues) {
  // docs/physics.md §2: for a = 1, 2h = 2 the dominant mode has κ ≈ 2.00897, E ≈ 2.0544 (Stewartson).
  const auto modes = exact::cylinder_modes(1.0, 2.0, 3, 40.0);
  ASSERT_FALSE(modes.empty());
  std::printf("dominant cylinder mode: kappa %.12f (Stewartson: 2.00897), E %.12f (2.0544)\n", modes[0].kappa,
              modes[0].E);
  EXPECT_NEAR(modes[0].kappa, 2.00897, 5e-6);
  EXPECT_NEAR(modes[0].E, 2.0544, 5e-5);
  EXPECT_EQ(modes[0].axial, 0);
  EXPECT_EQ(modes[0].radial, 1);
  // Every root satisfies the dispersion relation ξ J1′(ξ) + κ J1(ξ) = 0 with ξ² = (ka)²(κ² − 1).
  for (const auto& m : modes) {
    const double k = (2 * m.axial + 1) * std::numbers::pi / 2.0, xi = k * std::sqrt(m.kappa * m.kappa - 1);
    const double j0 = std::cyl_bessel_j(0.0, xi), j1 = std::cyl_bessel_j(1.0, xi);
    EXPECT_NEAR(xi * j0 - j1 + m.kappa * j1, 0.0, 1e-10 * std::max(1.0, xi));
  }
}
