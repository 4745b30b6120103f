// Finite-element forms of the m = 1 linearised Navier–Stokes eigenproblem in the rotating frame, and their
// real 2 × 2 block form for PETSc's real scalars (docs/viscous.md, "Equations" and "Why a real block form").
//
// In the circular components of taylor_hood_space.hpp, with e^{iλt} time dependence, ω0 = 1 and the
// Ekman number Ek = ν/(ω0 L²), the weak form of
//   iλ V + 2 ẑ × V + ∇P = Ek ΔV,   div V = 0,   V = 0 on the wall
// becomes, with the pressure rescaled to Q = iP, the complex symmetric pencil
//   A x = λ 𝓜 x,   A = [[−C + i Ek K, Bᵀ], [B, 0]],   𝓜 = [[M, 0], [0, 0]],
// where, on the meridian half-section (measure dr dz),
//   M = diag(½ M0, ½ M0, M0),           M0 = ∫∫ v u r
//   C = diag(M0, −M0, 0)                 (Coriolis: (2ẑ × V)± = ±2i u±)
//   K = diag(½ K2, ½ K0, K1),            K_m = ∫∫ (v_r u_r + v_z u_z + m² v u / r²) r   (vector Laplacian:
//                                        (ΔV)± = Δ_{1±1} u±, (ΔV)_z = Δ_1 u_z)
//   B: q ↦ ∫∫ q [½ (r u+_r + 2 u+) + ½ r u−_r + r u_z,z]   (r div V for m = 1).
// A partially filled tank (the mesh has free edges r = b; docs/viscous.md, "Partially filled tanks"): the free surface
// is stress-free, so K becomes the stress form 2∫∫ D(V):D(W̄) = K + ∫∫ ∇V:(∇W̄)ᵀ (equal to K for no-slip walls in
// the continuum, not on a free surface); its displacement η (outward along r, iλη = V_r) enters through the normal
// stress −P + 2Ek ∂_n V_n = b η, as unknowns η̃ = iη after the pressure with
//   A += b²/2 ∫ η̃ (w+ + w−) dz (and its transpose),   𝓜 += b² ∫ η̃ ζ dz,   f += −b² ∫ z' η̃ dz,
// so that x̄ᵀ𝓜x = ∫∫|V|² r dr dz + b² ∫|η|² dz is the energy of docs/physics.md §2 ("Partially filled tanks") and
// E = π (fᵀx)²/xᵀ𝓜x its coupling about the liquid's centroid.
// Ideal limit: Ek = 0 gives a real symmetric pencil whose Rayleigh quotient −xᵀCx / xᵀMx lies in [−2, 2].
// With Ek > 0, Im λ = Ek x̄ᵀKx / x̄ᵀMx > 0: every mode decays as e^{−Im λ t}.
//
// The coupling to the body's tilt is (e1 × r, V) = iπ fᵀx with f(v) = ∫∫ (−z' v− + r v_z) r, z' = z − z_c, and
// ‖V‖² = 2π x̄ᵀ𝓜x; for a real (ideal) mode E = 2|(e1 × r, V)|²/‖V‖² = π (fᵀx)² / xᵀ𝓜x (docs/physics.md §2).
#pragma once

#include "petsc_handles.hpp"
#include "taylor_hood_space.hpp"

#include <mpi.h>

#include <complex>

namespace rc::modes {

// The complex pencil written over the reals: unknown j of the complex problem is the pair (2j, 2j + 1) =
// (Re x_j, Im x_j), and
//   Â = [[Ar, −Ai], [Ai, Ar]] pairwise,  M̂ = diag(𝓜, 𝓜) pairwise,  Ar = Re A,  Ai = Im A = Ek [[K, 0], [0, 0]].
// Each complex eigenvalue λ of (A, 𝓜) is an eigenvalue of (Â, M̂) with the eigenvector pairs (x_j, −i x_j);
// its conjugate is the eigenvalue of the conjugate problem (growing, Im < 0), never physical.
struct ViscousForms {
  int complex_size = 0;    // unknowns of the complex problem (velocity, pressure and any free surface's η̃)
  PMat A, M;               // Â (holding explicit zeros on M̂'s and iM's patterns), M̂ (distributed over the ranks)
  PMat iM;                 // the block form of i𝓜: [[0, −𝓜], [𝓜, 0]] pairwise (complex shifts σ𝓜 = Re σ M̂ + Im σ iM)
  PVec coupling;           // f on the real slots, 0 on the imaginary ones
  PVec offset_coupling;    // with a free surface only: g, the coupling per unit height of the centroid above the
                           // joint (a_O = a + c t, docs/physics.md §2): g(v) = −∫∫ v− r dr dz − b² ∫ η̃ dz
  PVec real_slots;         // 1 on the real slots, 0 on the imaginary ones
  PVec mass_diagonal;      // diagonal of M̂ (for scaling checks)
  bool complex_symmetric = false;  // Aᵀ = A and 𝓜ᵀ = 𝓜 as complex matrices (the meridian forms above): σ𝓜 − A is then
                                   // factored as LDLᵀ (complex_lu.hpp), not LU
};

// xᵀy (no conjugate) of two complex vectors in the block form above (pairs (Re, Im), each pair on one rank), summed
// over the vectors' communicator.
std::complex<double> block_bilinear(Vec x, Vec y);

// Assembles on `comm`: each rank integrates a contiguous share of the elements; PETSc's COO assembly sends
// the entries to the ranks that own their rows. ekman >= 0. Without `coriolis` A has no −C: the Stokes operator of the
// strong-viscosity expansion (stokes_series.hpp).
ViscousForms assemble_viscous_forms(const TaylorHoodSpace& space, double centroid_z, double ekman, MPI_Comm comm,
                                    bool coriolis = true);

}  // namespace rc::modes
