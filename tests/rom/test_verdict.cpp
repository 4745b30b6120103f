// The verdict with dissipation (rom/analysis/spectrum.hpp, docs/rom.md "Verdict with dissipation"): a root that grows is never
// "stable", however slowly, once its growth is above rounding (kGrowthNoise of the spectral radius); roots at
// sigma = 0 within the tolerance are neutral. Before, growth under 1e-7 of the oscillating roots' size counted as
// neutral: a precession growing at 2.5e-4 1/s beside a nutation at 3000 rad/s was called stable.
#include "chain_model.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <complex>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

ChainModel dissipative_model() {
  ChainModel m;
  m.n = 1;
  m.viscous = true;
  m.D = Eigen::MatrixXd::Zero(1, 1);
  return m;
}

Eigen::VectorXcd roots(std::initializer_list<cd> list) {
  Eigen::VectorXcd v(static_cast<Eigen::Index>(list.size()));
  Eigen::Index i = 0;
  for (const cd z : list) v[i++] = z;
  return v;
}
}  // namespace

TEST(Verdict, SlowPhysicalGrowthIsUnstable) {
  const ChainModel m = dissipative_model();
  // A nutation at -3000 rad/s that decays, a precession at -2.2 rad/s growing at 2.5e-4 1/s (8e-8 of 3000).
  const Verdict v = verdict_from_roots(m, roots({{-3000, 0.5}, {-2.2, -2.5e-4}}));
  EXPECT_FALSE(v.stable);
  EXPECT_EQ(v.growing, 1);
  EXPECT_DOUBLE_EQ(v.growth, 2.5e-4);
  EXPECT_LT(v.growth, v.tolerance);  // the old rule (growth <= tolerance) would have called it stable
}

TEST(Verdict, RoundingAndZeroRootsAreNeutral) {
  const ChainModel m = dissipative_model();
  // Growth of 1e-13 of the spectral radius is rounding; a root within the tolerance of sigma = 0 is left out.
  const Verdict v = verdict_from_roots(m, roots({{-3000, 0.5}, {-2.2, -3000 * 1e-13}, {1e-6, -1e-6}}));
  EXPECT_TRUE(v.stable);
  EXPECT_EQ(v.growing, 0);
  EXPECT_EQ(v.at_zero, 1);
  EXPECT_LT(v.growth, v.noise);
}

TEST(Verdict, EveryRootDecaying) {
  const ChainModel m = dissipative_model();
  const Verdict v = verdict_from_roots(m, roots({{-3000, 0.5}, {-2.2, 1e-3}}));
  EXPECT_TRUE(v.stable);
  EXPECT_DOUBLE_EQ(v.growth, -1e-3);  // the slowest decay
  EXPECT_DOUBLE_EQ(v.margin, v.growth);
}

}  // namespace rc::rom
