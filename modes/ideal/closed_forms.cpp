#include "closed_forms.hpp"

#include "gauss_rules.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace rc::modes::exact {
namespace {


double J0(double x) { return std::cyl_bessel_j(0.0, x); }
double J1(double x) { return std::cyl_bessel_j(1.0, x); }
double J1prime(double x) { return J0(x) - J1(x) / x; }
double Y0(double x) { return std::cyl_neumann(0.0, x); }
double Y1(double x) { return std::cyl_neumann(1.0, x); }

// E of p = F(q r) sin(k z) on b < r < a, |z| < h, with the docs/physics.md §2 formulas (ω0 = 1), by tensor
// Gauss–Legendre quadrature; F and dF are the radial function and its derivative in their argument.
double mode_energy(double b, double a, double h, double k, double q, double lambda,
                   const std::function<double(double)>& F, const std::function<double(double)>& dF) {
  static std::vector<double> gx, gw;
  if (gx.empty()) gauss_legendre(96, gx, gw);
  const double D = 4 - lambda * lambda;
  double coupling = 0, norm = 0;
  for (std::size_t i = 0; i < gx.size(); ++i) {
    const double r = b + 0.5 * (a - b) * (gx[i] + 1), wr = 0.5 * (a - b) * gw[i];
    const double f = F(q * r), fr = q * dF(q * r);  // F(qr) and d/dr
    const double rp_r = f + r * fr;                  // (r F)_r
    for (std::size_t l = 0; l < gx.size(); ++l) {
      const double z = h * gx[l], wz = h * gw[l], w = wr * wz;
      const double s = std::sin(k * z), c = std::cos(k * z);
      const double p = f * s, pr = fr * s, pz = f * k * c;
      coupling += (z * rp_r * s / (2 - lambda) + r * r * pz / lambda) * w;
      const double Vr = (lambda * pr + 2 * p / r) / D, Vphi = (2 * pr + lambda * p / r) / D, Vz = pz / lambda;
      norm += (Vr * Vr + Vphi * Vphi + Vz * Vz) * r * w;
    }
  }
  coupling *= -std::numbers::pi;
  norm *= 2 * std::numbers::pi;
  return 2 * coupling * coupling / norm;
}

double cylinder_mode_energy(double a, double h, double k, double xi, double lambda) {
  return mode_energy(0, a, h, k, xi / a, lambda, J1, J1prime);
}

}  // namespace

// Bisection refined to machine precision on a bracket [lo, hi] with a sign change of f.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  double flo = f(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm < 0) == (flo < 0)) { lo = mid; flo = fm; } else { hi = mid; }
  }
  return 0.5 * (lo + hi);
}

// found(ξ) at each sign change of f on (0, max_xi), sampled every 1e-3 and bisected to machine precision.
void for_each_root(const std::function<double(double)>& f, double max_xi, const std::function<void(double)>& found) {
  const double step = 1e-3;
  double x0 = step, f0 = f(x0);
  for (double x1 = 2 * step; x1 < max_xi; x1 += step) {
    const double f1 = f(x1);
    if ((f0 < 0) != (f1 < 0)) found(bisect(f, x0, x1));
    x0 = x1;
    f0 = f1;
  }
}

SpheroidValues spheroid(double a, double c) {
  SpheroidValues s;
  s.volume = 4 * std::numbers::pi * a * a * c / 3;
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
    const double ka = (2 * n + 1) * std::numbers::pi / (2 * h) * a;
    for (int sign : {+1, -1}) {
      // Along the branch κ = ±sqrt(1 + ξ²/(ka)²), f(ξ) = ξ J0(ξ) + (κ − 1) J1(ξ) (since ξ J1′ = ξ J0 − J1).
      auto f = [&](double xi) {
        const double kappa = sign * std::sqrt(1 + xi * xi / (ka * ka));
        return xi * J0(xi) + (kappa - 1) * J1(xi);
      };
      int j = 0;
      for_each_root(f, max_xi, [&](double xi) {
        Mode m;
        m.kappa = sign * std::sqrt(1 + xi * xi / (ka * ka));
        m.lambda = 2 / m.kappa;
        m.axial = n;
        m.radial = ++j;
        m.E = cylinder_mode_energy(a, h, ka / a, xi, m.lambda);
        modes.push_back(m);
      });
    }
  }
  std::sort(modes.begin(), modes.end(), [](const Mode& x, const Mode& y) { return x.E > y.E; });
  return modes;
}

double cylinder_zhukovsky(double a, double height, int terms) {
  const double h = height / 2, mass = std::numbers::pi * a * a * height;
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

std::vector<Mode> annular_cylinder_modes(double b, double a, double height, int max_axial, double max_xi) {
  if (!(b > 0 && b < a)) throw std::invalid_argument("annular_cylinder_modes: needs 0 < inner radius < outer radius");
  const double h = height / 2, beta = b / a;
  std::vector<Mode> modes;
  for (int n = 0; n < max_axial; ++n) {
    const double ka = (2 * n + 1) * std::numbers::pi / (2 * h) * a;
    for (int sign : {+1, -1}) {
      const auto kappa_of = [&](double xi) { return sign * std::sqrt(1 + xi * xi / (ka * ka)); };
      // x F' + κ F at x for F = J1 and F = Y1 (x F' = x F0 − F1 for both kinds).
      const auto gJ = [&](double x, double kappa) { return x * J0(x) + (kappa - 1) * J1(x); };
      const auto gY = [&](double x, double kappa) { return x * Y0(x) + (kappa - 1) * Y1(x); };
      const auto D = [&](double xi) {
        const double kappa = kappa_of(xi);
        return gJ(xi, kappa) * gY(beta * xi, kappa) - gJ(beta * xi, kappa) * gY(xi, kappa);
      };
      int j = 0;
      for_each_root(D, max_xi, [&](double xi) {
        const double kappa = kappa_of(xi);
        // F = J1 + c Y1 with the outer wall's condition (or the rod's, where Y1's is near zero there).
        const double go = gY(xi, kappa), gi = gY(beta * xi, kappa);
        const double c = std::abs(go) > std::abs(gi) ? -gJ(xi, kappa) / go : -gJ(beta * xi, kappa) / gi;
        const auto F = [c](double x) { return J1(x) + c * Y1(x); };
        const auto dF = [c](double x) { return J1prime(x) + c * (Y0(x) - Y1(x) / x); };
        Mode m;
        m.kappa = kappa;
        m.lambda = 2 / kappa;
        m.axial = n;
        m.radial = ++j;
        m.E = mode_energy(b, a, h, ka / a, xi / a, m.lambda, F, dF);
        modes.push_back(m);
      });
    }
  }
  std::sort(modes.begin(), modes.end(), [](const Mode& x, const Mode& y) { return x.E > y.E; });
  return modes;
}

}  // namespace rc::modes::exact
