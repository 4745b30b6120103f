// The strongly viscous fluid's response as a series in 1/Ek (Kononov 1999, §2 after (18): the moment
// −ρRe P¹ω̇ + ρRe²(P²ω̈ + ω0 P³ω̇) + …, Re = 1/Ek, after Chernousko 1968; docs/viscous.md, "Strong viscosity: the Stokes
// limit and its next terms").
//
// With the pencil of viscous_forms.hpp, σ𝓜 − A = D(σ) − S_Ek, S_Ek = [[iEk K, Bᵀ], [B, 0]] the Stokes operator and
// D(σ) = [[σM + C, 0], [0, 0]] (inertia and Coriolis, velocity only). The velocity block of S_Ek⁻¹ is G/Ek, G that of
// S_1⁻¹ (the Stokes solution operator at Ek = 1, complex symmetric), and with f on the velocity only
//   R(σ) = π fᵀ(σ𝓜 − A)⁻¹f = −π Σ_n Ek^{−(n+1)} fᵀG (D(σ) G)ⁿ f = Σ_n r_n(σ)/Ek^{n+1},
//   r_0 = −π fᵀGf                          (Kononov's P¹: the Stokes flow, purely imaginary),
//   r_1(σ) = −π (σ x0ᵀMx0 + x0ᵀCx0)         (P², one time derivative more: ω̈; P³, the Coriolis term: ω0 ω̇),
//   r_2(σ) = −π (D x0)ᵀ G (D x0),           x0 = G f,
// convergent for Ek above |σM + C|·‖G‖. Four Stokes solves on one factorisation (S_1 without Coriolis).
#pragma once

#include "meridian_mesh.hpp"

#include <complex>

namespace rc::modes {

struct StokesSeries {
  std::complex<double> r0;            // −π fᵀGf
  std::complex<double> r1_s, r1_0;    // r_1(σ) = r1_s σ + r1_0
  std::complex<double> r2_ss, r2_s, r2_0;  // r_2(σ) = r2_ss σ² + r2_s σ + r2_0
  // Σ_{n < terms} r_n(σ)/Ek^{n+1} (terms 1 to 3).
  std::complex<double> response(std::complex<double> sigma, double ekman, int terms) const;
};

// The series' coefficients of a completely filled cavity on the mesh `mesh` of `shape` (the mesh of its viscous
// response at the Ekman numbers it is used at). Throws std::runtime_error for a partially filled one (its free
// surface's normal stress does not scale with Ek) or when a Stokes solve fails.
StokesSeries stokes_series(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh);

}  // namespace rc::modes
