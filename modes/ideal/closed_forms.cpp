#include "closed_forms.hpp"

#include "gauss_rules.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace rc::modes::exact {
namespace {

constexpr double kPi = std::numbers::pi;

double J0(double x) { return std::cyl_bessel_j(0.0, x); }
double J1(double x) { return std::cyl_bessel_j(1.0, x); }
double J1prime(double x) { return J0(x) - J1(x) / x; }

// Bisection refined to machine precision on a bracket [lo, hi] with a sign change of f.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  double flo = f(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm < 0) == (flo < 0)) { lo = mid; flo = fm; } else { hi = mid; }
  }
  return 0.5 * (lo + hi);
}

// E of p = J1(ξ r/a) sin(k z) with the docs/physics.md §2 formulas (ω0 = 1), by tensor Gauss–Legendre quadrature.
double cylinder_mode_energy(double a, double h, double k, double xi, double lambda) {
  static std::vector<double> gx, gw;
  if (gx.empty()) gauss_legendre(96, gx, gw);
  const double D = 4 - lambda * lambda, q = xi / a;
  double coupling = 0, norm = 0;
  for (std::size_t i = 0; i < gx.size(); ++i) {
    const double r = 0.5 * a * (gx[i] + 1), wr = 0.5 * a * gw[i];
    const double j1 = J1(q * r), j1r = q * J1prime(q * r);  // J1(qr) and d/dr
    const double rp_r = j1 + r * j1r;                        // (r J1)_r
    for (std::size_t l = 0; l < gx.size(); ++l) {
      const double z = h * gx[l], wz = h * gw[l], w = wr * wz;
      const double s = std::sin(k * z), c = std::cos(k * z);
      const double p = j1 * s, pr = j1r * s, pz = j1 * k * c;
      coupling += (z * rp_r * s / (2 - lambda) + r * r * pz / lambda) * w;
      const double Vr = (lambda * pr + 2 * p / r) / D, Vphi = (2 * pr + lambda * p / r) / D, Vz = pz / lambda;
      norm += (Vr * Vr + Vphi * Vphi + Vz * Vz) * r * w;
    }
  }
  coupling *= -kPi;
  norm *= 2 * kPi;
  return 2 * coupling * coupling / norm;
}

}  // namespace

SpheroidValues spheroid(double a, double c) {
  SpheroidValues s;
  s.volume = 4 * kPi * a * a * c / 3;
  s.A_f = s.volume * (a * a + c * c) / 5;
  s.J_zh = s.volume * (a * a - c * c) * (a * a - c * c) / (5 * (a * a + c * c));
  s.mode.lambda = 2 * a * a / (a * a + c * c);
  s.mode.kappa = 2 / s.mode.lambda;
  s.mode.E = 0.8 * s.volume * a * a * c * c / (a * a + c * c);
  return s;
}

std::vector<Mode> cylinder_modes(double a, double height, int max_axial, double max_xi) {
  const double h = height / 2;
  std::vector<Mode> modes;
  for (int n = 0; n < max_axial; ++n) {
    const double ka = (2 * n + 1) * kPi / (2 * h) * a;
    for (int sign : {+1, -1}) {
      // Along the branch κ = ±sqrt(1 + ξ²/(ka)²), f(ξ) = ξ J0(ξ) + (κ − 1) J1(ξ) (since ξ J1′ = ξ J0 − J1).
      auto f = [&](double xi) {
        const double kappa = sign * std::sqrt(1 + xi * xi / (ka * ka));
        return xi * J0(xi) + (kappa - 1) * J1(xi);
      };
      int j = 0;
      const double step = 1e-3;
      double x0 = step, f0 = f(x0);
      for (double x1 = 2 * step; x1 < max_xi; x1 += step) {
        const double f1 = f(x1);
        if ((f0 < 0) != (f1 < 0)) {
          const double xi = bisect(f, x0, x1);
          Mode m;
          m.kappa = sign * std::sqrt(1 + xi * xi / (ka * ka));
          m.lambda = 2 / m.kappa;
          m.axial = n;
          m.radial = ++j;
          m.E = cylinder_mode_energy(a, h, ka / a, xi, m.lambda);
          modes.push_back(m);
        }
        x0 = x1; f0 = f1;
      }
    }
  }
  std::sort(modes.begin(), modes.end(), [](const Mode& x, const Mode& y) { return x.E > y.E; });
  return modes;
}

double cylinder_zhukovsky(double a, double height, int terms) {
  const double h = height / 2, mass = kPi * a * a * height;
  // Roots of J1′(ξ) = J0(ξ) − J1(ξ)/ξ: one in each interval of length π beyond the first at ≈ 1.8412.
  auto g = [](double x) { return J1prime(x); };
  double sum = 0, x0 = 0.5;
  int found = 0;
  for (double x1 = x0 + 0.05; found < terms; x1 += 0.05) {
    if ((g(x0) < 0) != (g(x1) < 0)) {
      const double xi = bisect(g, x0, x1);
      sum += std::tanh(xi * h / a) / (xi * xi * xi * (xi * xi - 1));
      ++found;
    }
    x0 = x1;
  }
  return mass * (h * h / 3 - 3 * a * a / 4 + (8 * a * a * a / h) * sum);
}

}  // namespace rc::modes::exact
