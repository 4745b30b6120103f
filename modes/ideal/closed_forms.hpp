// Closed-form validation cases of docs/physics.md §2 (ρ = 1, ω0 = 1): the sphere and spheroid (one coupling mode
// each) and Stewartson's modes of the circular cylinder, plus the cylinder's Zhukovsky inertia series.
// Used by the tests and by the shipped reference tables; nothing here touches the FE solver.
#pragma once

#include <vector>

namespace rc::modes::exact {

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

// J_zh = m_f [h²/3 − 3a²/4 + (8a³/h) Σ_j tanh(ξ_j h/a) / (ξ_j³ (ξ_j² − 1))], J1′(ξ_j) = 0, h = half height.
double cylinder_zhukovsky(double a, double height, int terms = 4000);

}  // namespace rc::modes::exact
