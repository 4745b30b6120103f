// Closed-form validation cases of docs/physics.md §2 (ρ = 1, ω0 = 1): the sphere and spheroid (one coupling mode
// each) and Stewartson's modes of the circular cylinder, plus the cylinder's Zhukovsky inertia series.
// Used by the tests and by the shipped reference tables; nothing here touches the FE solver.
#pragma once

#include <functional>
#include <vector>

namespace rc::modes::exact {

// Bisection refined to machine precision on a bracket [lo, hi] with a sign change of f.
double bisect(const std::function<double(double)>& f, double lo, double hi);

// found(x) at each sign change of f on (0, max_xi), sampled every 1e-3 and bisected to machine precision.
void for_each_root(const std::function<double(double)>& f, double max_xi, const std::function<void(double)>& found);

struct Mode {
  double kappa = 0, lambda = 0, E = 0;
  int axial = 0;   // n: axial wavenumber k = (2n+1)π/(2h)  (cylinder only)
  int radial = 0;  // j: index of the root for this n and sign of κ, 1-based (cylinder only)
};

struct SpheroidValues {
  double volume, A_f, J_zh;
  Mode mode;  // the single coupling mode: λ = 2a²/(a² + c²), E = (4/5) m a² c²/(a² + c²)
};
// a: equatorial semi-axis, c: polar semi-axis (the sphere is a = c).
SpheroidValues spheroid(double a, double c);

// Stewartson's spinning-top modes of a cylinder of radius a and height 2h: p = J1(ξ r/a) sin(k z),
// k = (2n+1)π/(2h), ξ J1′(ξ) + κ J1(ξ) = 0, ξ² = (k a)²(κ² − 1), κ of either sign. E is the docs/physics.md §2
// integral evaluated by Gauss–Legendre quadrature of the exact fields. Returns the modes with
// n < max_axial and ξ < max_xi, sorted by E descending.
std::vector<Mode> cylinder_modes(double a, double height, int max_axial = 8, double max_xi = 60.0);

// The annular cylinder b < r < a, |z| < h (a rod of radius b inside the cylinder; no axis): p = F(ξ r/a) sin(k z),
// F = J1 + c Y1, k = (2n+1)π/(2h), x F′(x) + κ F(x) = 0 at x = ξ and x = ξ b/a (the walls' u_r = 0), ξ² = (k a)²(κ² − 1):
// det [[gJ(ξ), gY(ξ)], [gJ(ξ b/a), gY(ξ b/a)]] = 0 with gF(x) = x F0(x) + (κ − 1) F1(x) (docs/physics.md, "Annular
// cylinder"). E by quadrature as for the full cylinder. Sorted by E descending.
std::vector<Mode> annular_cylinder_modes(double b, double a, double height, int max_axial = 8, double max_xi = 60.0);

// J_zh = m_f [h²/3 − 3a²/4 + (8a³/h) Σ_j tanh(ξ_j h/a) / (ξ_j³ (ξ_j² − 1))], J1′(ξ_j) = 0, h = half height.
double cylinder_zhukovsky(double a, double height, int terms = 4000);

}  // namespace rc::modes::exact
