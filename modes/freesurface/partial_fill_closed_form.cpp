#include "partial_fill_closed_form.hpp"

#include "closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes::exact {
namespace {

// x F′(x) + β F(x) for each kind of radial function, through x F1′ = x F0 − F1 (J, Y, I) and x K1′ = −x K0 − K1.
double gJ(double x, double beta) { return x * std::cyl_bessel_j(0.0, x) + (beta - 1) * std::cyl_bessel_j(1.0, x); }
double gY(double x, double beta) { return x * std::cyl_neumann(0.0, x) + (beta - 1) * std::cyl_neumann(1.0, x); }
double gI(double x, double beta) { return x * std::cyl_bessel_i(0.0, x) + (beta - 1) * std::cyl_bessel_i(1.0, x); }
double gK(double x, double beta) { return -x * std::cyl_bessel_k(0.0, x) + (beta - 1) * std::cyl_bessel_k(1.0, x); }

// The free surface's coefficient: r p_r + (κ − D) p = 0 with D = 4 − λ² = 4 − 4/κ².
double surface_beta(double kappa) { return kappa - 4 + 4 / (kappa * kappa); }

}  // namespace

double partial_fill_surface_radius(double a, double fill) {
  if (!(fill > 0 && fill <= 1)) throw std::invalid_argument("the fill must be in (0, 1]");
  return a * std::sqrt(1 - fill);
}

std::vector<PartialFillMode> partially_filled_cylinder_modes(double a, double height, double fill, int max_axial,
                                                             double max_xi) {
  if (!(fill > 0 && fill < 1)) throw std::invalid_argument("partially_filled_cylinder_modes: needs 0 < fill < 1");
  const double beta_r = partial_fill_surface_radius(a, fill) / a, h = height / 2;
  std::vector<PartialFillMode> modes;
  for (int n = 0; n < max_axial; ++n) {
    const double ka = (2 * n + 1) * std::numbers::pi / (2 * h) * a;
    for (const int sign : {+1, -1}) {
      const auto add = [&](double kappa, int j) {
        PartialFillMode m;
        m.kappa = kappa;
        m.lambda = 2 / kappa;
        m.axial = n;
        m.radial = j;
        modes.push_back(m);
      };
      // |λ| > 2: κ = ±√(1 − ζ²/(ka)²), ζ in (0, ka); the determinant of both conditions for F = I1 + c K1.
      const auto kappa_b = [&](double zeta) { return sign * std::sqrt(std::max(0.0, 1 - zeta * zeta / (ka * ka))); };
      const auto detB = [&](double zeta) {
        const double kappa = kappa_b(zeta), bs = surface_beta(kappa);
        return gI(zeta, kappa) * gK(beta_r * zeta, bs) - gI(beta_r * zeta, bs) * gK(zeta, kappa);
      };
      for_each_root(detB, ka * (1 - 1e-9), [&](double zeta) { add(kappa_b(zeta), 0); });
      // |λ| < 2: κ = ±√(1 + ξ²/(ka)²); F = J1 + c Y1.
      const auto kappa_a = [&](double xi) { return sign * std::sqrt(1 + xi * xi / (ka * ka)); };
      const auto detA = [&](double xi) {
        const double kappa = kappa_a(xi), bs = surface_beta(kappa);
        return gJ(xi, kappa) * gY(beta_r * xi, bs) - gJ(beta_r * xi, bs) * gY(xi, kappa);
      };
      int j = 0;
      for_each_root(detA, max_xi, [&](double xi) { add(kappa_a(xi), ++j); });
    }
  }
  return modes;
}

}  // namespace rc::modes::exact
