// Coupling of a partially filled tank's mode to the body's rotation (docs/physics.md §2, "Partially filled tanks:
// coupling to the body").
//
// The state of the liquid is (V, η): its velocity and the free surface's outward displacement, with the energy
// ‖W‖² = ∫|V|² dτ + b ∫|η|² dS (kinetic, and the surface's potential energy in the centrifugal field, ω0 = ρ = 1).
// A rotation Ω of the body about a point O on its axis forces the liquid along one direction of that space,
//   U_O = (P_D(e1 × r_O), z_O (e1·r)/b),
// P_D the projection with the potential zero on the free surface, z_O the height above O. Its coupling is
// a = ⟨U_O, W⟩/‖W‖ and E = 2a², as E = 2a²/N² for a completely filled cavity; the sum over all modes is
// ‖U_O‖² = A_f(O) + K(O) − J_D(O) (Zhukovsky's inertia with the free surface held at zero potential, and
// K(O) = π b² ∫ z_O² dz over the free surface's height).
//
// With the scaled field Ṽ = λ D V (D = 4 − λ², as in coupling.hpp) the surface displacement is η̃ = −λ D p/b and
// everything is a form value of p (m = 1, real p):
//   ⟨U_c, W̃⟩  = π [(λ² + 2λ) f1·p + D f2·p + λ D f3·p]     (about the liquid's centroid, z′ = z − z_c),
//   ⟨T, W̃⟩    = π [(λ² + 2λ) g1·p + λ D e1·p]              (per unit height of the centroid above O: U_O = U_c + c T),
//   ‖W̃‖²     = 2π [λ²(λ² + 4) pᵀKh p + 4λ³ pᵀGc p + D² pᵀKz p + λ² D² ∫_{r=b} p² dz],
// with f3(q) = b ∫_{r=b} z′ q dz, g1(q) = ∫∫ (r q)_r dr dz, e1(q) = b ∫_{r=b} q dz. Without a free surface f3, e1
// and the surface energy vanish and g1·p = 0 for every mode with λ ≠ 0 (a filled cavity's mode has no momentum), so
// this is coupling.hpp's formula.
#pragma once

namespace rc::modes {

struct FreeSurfaceFormValues {
  double f1p = 0, f2p = 0;  // the coupling functionals of poincare_forms.hpp (z′ from the liquid's centroid)
  double f3p = 0;           // b ∫_{r=b} z′ p dz
  double g1p = 0;           // ∫∫ (r p)_r dr dz
  double e1p = 0;           // b ∫_{r=b} p dz
  double kh = 0, gc = 0, kz = 0;  // pᵀKh p, pᵀGc p, pᵀKz p
  double ss = 0;            // ∫_{r=b} p² dz
};

struct FreeSurfaceCoupling {
  double a = 0;  // ⟨U_c, W⟩ for ‖W‖ = 1: the coupling about the liquid's centroid
  double t = 0;  // ⟨T, W⟩ for ‖W‖ = 1: about a point O at height −c below the centroid, a_O = a + c t
  double E = 0;  // 2 a²
  double norm = 0;  // ‖W̃‖ of the pressure as given: the normalised mode is W̃/‖W̃‖ (free_surface_fields.hpp)
};

// Throws std::runtime_error if the form values are not finite. A field of zero energy (λ = 0 with Kz p = 0, the
// steady geostrophic motions, or the exact eigenvalues λ = ±2 where p does not give the velocity) couples to nothing.
FreeSurfaceCoupling free_surface_coupling(double lambda, const FreeSurfaceFormValues& v);

// E about a point at height −c below the centroid: 2 (a + c t)².
inline double coupling_about(const FreeSurfaceCoupling& k, double c) { return 2 * (k.a + c * k.t) * (k.a + c * k.t); }

}  // namespace rc::modes
