// The response fit (modes/viscous/rational_fit.hpp) on functions whose poles and values are known: a modal sum
// it must recover pole by pole, a continuous spectrum (a logarithm: a segment of poles) it must approximate
// between the samples, and a pole a passive fluid cannot have, which it must drop and say so in its error.
#include "rational_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

using rc::modes::fit_response;
using C = std::complex<double>;

namespace {

std::vector<double> grid(double lo, double hi, int n) {
  std::vector<double> z;
  for (int i = 0; i < n; ++i) z.push_back(lo + (hi - lo) * i / (n - 1));
  return z;
}

}  // namespace

TEST(RationalFit, RecoversTheModesOfAModalSum) {
  // Six damped modes, two of them 0.01 apart (a close pair like the viscous spectrum near a cluster).
  const std::vector<C> p = {{1.0, 0.01}, {1.01, 0.02}, {-0.5, 0.05}, {0.3, 0.003}, {1.7, 0.2}, {-1.4, 0.1}};
  const std::vector<C> r = {{1.5, -0.02}, {0.2, 0.1}, {0.3, 0.0}, {0.01, 0.001}, {0.5, 0.3}, {0.1, -0.05}};
  const auto z = grid(-3, 3, 1201);
  std::vector<C> f;
  for (double s : z) {
    C v = 0;
    for (std::size_t j = 0; j < p.size(); ++j) v += r[j] / (s - p[j]);
    f.push_back(v);
  }
  const auto fit = fit_response(z, f, 1e-12);
  std::printf("AAA degree %d, %zu poles kept, %d dropped, fit error %.1e\n", fit.aaa_degree, fit.poles.size(),
              fit.dropped_poles, fit.fit_error);
  ASSERT_EQ(fit.poles.size(), p.size());
  for (std::size_t j = 0; j < p.size(); ++j) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < fit.poles.size(); ++i)
      if (std::abs(fit.poles[i] - p[j]) < std::abs(fit.poles[best] - p[j])) best = i;
    const double dp = std::abs(fit.poles[best] - p[j]), dr = std::abs(fit.residues[best] - r[j]) / std::abs(r[j]);
    std::printf("  pole %+.3f%+.3fi: |dp| = %.1e, residue rel. error %.1e\n", p[j].real(), p[j].imag(), dp, dr);
    EXPECT_LE(dp, 1e-9);
    EXPECT_LE(dr, 1e-8);
  }
  EXPECT_LE(fit.fit_error, 1e-12);
}

TEST(RationalFit, ApproximatesAContinuousSpectrumBetweenItsSamples) {
  // R(s) = ∫_0^1 dt / (s − t − 0.02i) = log((s − 1 − 0.02i)/(s − 0.02i)): no discrete pole, a segment of them
  // 0.02 above the axis. Fitted on even samples, checked on the odd ones in between.
  const auto f_exact = [](double s) { return std::log((C(s, 0) - C(1, 0.02)) / (C(s, 0) - C(0, 0.02))); };
  const auto all = grid(-2, 3, 2001);
  std::vector<double> z, held;
  std::vector<C> f;
  for (std::size_t i = 0; i < all.size(); ++i) (i % 2 ? held : z).push_back(all[i]);
  for (double s : z) f.push_back(f_exact(s));
  const auto fit = fit_response(z, f, 1e-10);
  double worst = 0, scale = 0;
  for (double s : held) {
    worst = std::max(worst, std::abs(fit(s) - f_exact(s)));
    scale = std::max(scale, std::abs(f_exact(s)));
  }
  std::printf("AAA degree %d, %zu poles kept, %d dropped; fit error %.1e, between the samples %.1e\n",
              fit.aaa_degree, fit.poles.size(), fit.dropped_poles, fit.fit_error, worst / scale);
  EXPECT_LE(fit.fit_error, 1e-9);
  EXPECT_LE(worst / scale, 1e-8);
  for (const auto q : fit.poles) EXPECT_GT(q.imag(), 0);
}

TEST(RationalFit, DropsAPoleAPassiveFluidCannotHaveAndReportsTheCost) {
  // A growing "mode" (Im p < 0) is not a fluid's: it is dropped, and the error shows what it carried.
  const auto z = grid(-2, 2, 401);
  std::vector<C> f;
  for (double s : z) f.push_back(1.0 / (s - C(1, 0.05)) + 0.1 / (s - C(-1, -0.1)));
  const auto fit = fit_response(z, f, 1e-12);
  std::printf("%zu poles kept, %d dropped, fit error %.2e\n", fit.poles.size(), fit.dropped_poles, fit.fit_error);
  EXPECT_GE(fit.dropped_poles, 1);
  for (const auto q : fit.poles) EXPECT_GT(q.imag(), 0);
  EXPECT_GT(fit.fit_error, 1e-3);
}

TEST(RationalFit, RefusesBadSamples) {
  EXPECT_THROW(fit_response({0, 1, 2}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(fit_response({0, 1, 2, 3}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(fit_response({0, 1, 2, 3}, {1.0, 2.0, C(NAN, 0), 3.0}), std::invalid_argument);
}
