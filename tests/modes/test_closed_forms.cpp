// The closed forms themselves (modes/ideal/closed_forms.hpp) against numbers published independently of them.
#include "closed_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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

// The annular cylinder's closed form (closed_forms.hpp): each root satisfies both walls' condition with its own
// c of F = J1 + c Y1, and as the rod thins (b → 0) the leading modes become Stewartson's of the full cylinder
// (the rod's condition then only fixes c → 0: Y1 is singular at the axis).
TEST(ClosedForms, AnnularCylinderTendsToTheFullCylinder) {
  const auto full = rc::modes::exact::cylinder_modes(1.0, 2.0, 3, 30.0);
  const auto thin = rc::modes::exact::annular_cylinder_modes(1e-4, 1.0, 2.0, 3, 30.0);
  const auto ring = rc::modes::exact::annular_cylinder_modes(0.3, 1.0, 2.0, 3, 30.0);
  ASSERT_GE(thin.size(), 3u);
  ASSERT_GE(ring.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    std::printf("mode %d: full cylinder kappa %.10f E %.8f; rod 1e-4: kappa %.10f E %.8f; rod 0.3: kappa %.10f E %.8f\n",
                i + 1, full[i].kappa, full[i].E, thin[i].kappa, thin[i].E, ring[i].kappa, ring[i].E);
    EXPECT_NEAR(thin[i].kappa, full[i].kappa, 1e-6 * std::abs(full[i].kappa));
    EXPECT_NEAR(thin[i].E, full[i].E, 1e-5 * full[i].E);
  }
  // The rod takes liquid near the axis away: the leading mode's weight falls.
  EXPECT_LT(ring[0].E, full[0].E);
}
