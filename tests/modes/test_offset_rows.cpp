// offset_rows (modes/viscous/offset_rows.hpp): a symmetric 2 × 2 residue matrix [[ff, fg], [fg, gg]] as two rows whose
// 2(a + c t)² sum to ff + 2c fg + c² gg at every c — either pivot, and the case of a vanishing diagonal.
#include "offset_rows.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <cstdio>

using rc::modes::offset_rows;
using cd = std::complex<double>;

TEST(OffsetRows, TwoRowsAreTheResidueMatrixAtEveryOffset) {
  const cd cases[][3] = {{{1.6, 0.04}, {-0.3, 0.01}, {0.2, -0.002}},   // ff the pivot
                         {{0.01, 0.0}, {0.05, 0.02}, {0.9, 0.1}},      // gg the pivot
                         {{1.2, -0.1}, {0.0, 0.0}, {0.4, 0.03}},       // fg = 0 (mid-plane symmetry)
                         {{2.0, 0.1}, {0.6, 0.03}, {0.18, 0.018}},     // nearly rank one (a damped mode's)
                         {{0.0, 0.0}, {0.7, -0.2}, {0.0, 0.0}}};       // both diagonals 0
  double worst = 0;
  for (const auto& m : cases) {
    const auto rows = offset_rows(m[0], m[1], m[2]);
    for (const double c : {0.0, 1.0, -2.5, 7.0}) {
      const cd want = m[0] + 2 * c * m[1] + c * c * m[2];
      cd got = 0;
      for (const auto& r : rows) got += 2.0 * (r.a + c * r.t) * (r.a + c * r.t);
      worst = std::max(worst, std::abs(got - want) / std::max(std::abs(m[0]) + std::abs(m[1]) + std::abs(m[2]), 1e-300));
    }
    for (const auto& r : rows) EXPECT_TRUE(r.a.real() > 0 || (r.a.real() == 0 && r.a.imag() >= 0));
  }
  std::printf("sum of the two rows' 2(a + c t)^2 against ff + 2c fg + c^2 gg: worst %.2e of the entries\n", worst);
  EXPECT_LT(worst, 1e-14);
}
