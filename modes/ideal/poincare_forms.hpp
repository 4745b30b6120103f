// Finite-element forms of the rotating-fluid eigenproblem on the meridian half-section (docs/physics.md §2, m = 1):
//   Kh = ∫∫ (q_r p_r + q p / r²) r dr dz,   Kz = ∫∫ q_z p_z r dr dz,   Gc = ∫∫ (q_r p + q p_r) dr dz,
// so that λ² (Kh + Kz) + 2 λ Gc − 4 Kz = 0 (ω0 = 1), and the linear functionals that give the coupling
// (e1 × r, V) and the Zhukovsky right-hand side, with z' = z − z_c measured from the fluid centroid:
//   f1(q) = ∫∫ z' (r q)_r dr dz,   f2(q) = ∫∫ r² q_z dr dz.
#pragma once

#include "fe_space.hpp"
#include "petsc_handles.hpp"

namespace rc::modes {

// Mass properties of the frozen fluid for ρ = 1 (docs/physics.md §4 root attributes).
struct FluidIntegrals {
  double volume = 0;      // 2π ∫∫ r dr dz
  double centroid_z = 0;  // 2π ∫∫ z r dr dz / volume
  double A_f = 0;         // transverse inertia about the centroid: π ∫∫ (r² + 2 z'²) r dr dz
  double C_f = 0;         // axial inertia: 2π ∫∫ r³ dr dz
};
FluidIntegrals integrate_fluid(const FESpace& space);
// The same from the meridian moments ∫∫ r, ∫∫ z r, ∫∫ z² r, ∫∫ r³ (dr dz).
FluidIntegrals fluid_from_moments(double r1, double zr, double zzr, double r3);

struct PoincareForms {
  PMat Kh, Kz, Gc;
  PMat M;            // Kh + Kz: the λ² coefficient, and the Zhukovsky (Laplacian, m = 1) stiffness
  PVec f1, f2;       // coupling functionals (see above)
  PVec zhukovsky_rhs;  // f1 − f2 = ∫∫ (e1 × r)·∇q in the meridian representation (docs/physics.md §2)
};
PoincareForms assemble_poincare_forms(const FESpace& space, double centroid_z);

}  // namespace rc::modes
