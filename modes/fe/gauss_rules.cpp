#include "gauss_rules.hpp"

#include <cmath>
#include <numbers>

namespace rc::modes {
namespace {

// P_n(t) and P_{n-1}(t) by the three-term recurrence.
void legendre(int n, double t, double& pn, double& pn1) {
  double p0 = 1, p1 = t;
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  pn = n == 0 ? 1 : p1;
  pn1 = n == 0 ? 0 : p0;
}

}  // namespace

void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double t = -std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double pn = 0, pn1 = 0;
      legendre(n, t, pn, pn1);
      dp = n * (t * pn - pn1) / (t * t - 1);
      const double dt = pn / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    x[i] = t;
    w[i] = 2 / ((1 - t * t) * dp * dp);
  }
}

std::vector<double> gauss_lobatto_points(int n) {
  std::vector<double> x(n + 1);
  x[0] = -1;
  x[n] = 1;
  // Interior points: roots of P_n′, by Newton on q(t) = P_n′(t) with q′ from the Legendre equation
  // (1 − t²) P_n″ = 2t P_n′ − n(n + 1) P_n, started from the Chebyshev–Gauss–Lobatto points.
  for (int i = 1; i < n; ++i) {
    double t = -std::cos(std::numbers::pi * i / n);
    for (int it = 0; it < 100; ++it) {
      double pn = 0, pn1 = 0;
      legendre(n, t, pn, pn1);
      const double d1 = n * (pn1 - t * pn) / (1 - t * t);
      const double d2 = (2 * t * d1 - n * (n + 1) * pn) / (1 - t * t);
      const double dt = d1 / d2;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    x[i] = t;
  }
  return x;
}

}  // namespace rc::modes
