// The free chain's partially filled tanks (rom/general/free_recoil.hpp): which layouts decouple the liquid's axial
// recoil from the tilts. The chain itself is checked against (26)'s free chain in tests/scenes/fill_3d_check.py.
#include "free_recoil.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace rc::rom {
namespace {

// A body whose partially filled tanks (radius 0.3 m, recoiling) sit at the given angles and distances, with the masses.
std::vector<GeneralBody> recoiling_craft(const std::vector<double>& degrees, const std::vector<double>& arms,
                               const std::vector<double>& masses) {
  GeneralBody b;
  for (std::size_t i = 0; i < degrees.size(); ++i) {
    GeneralTank t;
    t.recoil = true;
    t.scale = 0.3;
    t.mass = masses[i];
    const double a = degrees[i] * std::numbers::pi / 180;
    t.centroid = Eigen::Vector3d(arms[i] * std::cos(a), arms[i] * std::sin(a), 0.1);
    b.tanks.push_back(t);
  }
  return {b};
}

bool layout_taken(const std::vector<GeneralBody>& bodies) {
  try {
    require_symmetric_layout(Scene{}, bodies);
    return true;
  } catch (const SceneError&) {
    return false;
  }
}

TEST(FreeRecoil, LayoutsATurnMapsOntoThemselvesAreTaken) {
  EXPECT_TRUE(layout_taken(recoiling_craft({0, 180}, {0.6, 0.6}, {50, 50})));
  EXPECT_TRUE(layout_taken(recoiling_craft({30, 150, 270}, {0.6, 0.6, 0.6}, {50, 50, 50})));
  EXPECT_TRUE(layout_taken(recoiling_craft({0, 90, 180, 270}, {0.6, 0.6, 0.6, 0.6}, {50, 50, 50, 50})));
  // Two tanks on the axis whose meshed centroids err by 1e-6 of the tank.
  EXPECT_TRUE(layout_taken(recoiling_craft({0, 200}, {3e-7, 2e-7}, {50, 50})));
}

TEST(FreeRecoil, BalancedLayoutsWithoutTheSymmetryAreRefused) {
  // In balance (Σ m r = 0) but mapped onto itself by no turn: unequal tanks opposite, and three at 0, 90, 225 degrees.
  EXPECT_FALSE(layout_taken(recoiling_craft({0, 180}, {0.6, 0.3}, {50, 100})));
  const double r = 0.6, m1 = 50, m3 = m1 * std::sqrt(2.0);  // m1 (1, 0) + m1 (0, 1) + m3 (−1, −1)/√2 = 0
  EXPECT_FALSE(layout_taken(recoiling_craft({0, 90, 225}, {r, r, r}, {m1, m1, m3})));
  // Equal tanks at 0 and 180 degrees with one at 90: no turn maps it onto itself.
  EXPECT_FALSE(layout_taken(recoiling_craft({0, 90, 180}, {0.6, 0.6, 0.6}, {50, 50, 50})));
}

}  // namespace
}  // namespace rc::rom
