// Finite-element forms of the linearised Navier–Stokes eigenproblem in a 3-D cavity turning about z (docs/volume.md
// §7), in the real block form the meridian solver uses (viscous_forms.hpp, block_pencil.hpp), so that the damped-mode
// solver (viscous_eigensolver.hpp) takes them unchanged.
//
// With e^{iλt}, ω0 = 1 and Ek = ν/(ω0 L²), the weak form of
//   iλ V + 2ẑ × V + ∇P = Ek ΔV,   div V = 0,   V = 0 on the wall,
// tested with real W and q, multiplied by −i and with the pressure rescaled to Q = −iP, is the complex pencil
//   A x = λ 𝓜 x,   A = [[i (C + Ek K), Bᵀ], [B, 0]],   𝓜 = [[M, 0], [0, 0]],
//   M = diag(M0, M0, M0),  M0 = ∫ w v,      K = diag(K0, K0, K0),  K0 = ∫ ∇w·∇v,      B: q ↦ ∫ q div V,
//   C = [[0, −2M0, 0], [2M0, 0, 0], [0, 0, 0]]   (∫ W·(2ẑ × V) = 2∫ (W_y V_x − W_x V_y): the Coriolis term).
// C is antisymmetric, so A is not complex symmetric as the meridian pencil is (the m = 1 reduction's circular
// components make C diagonal there): the left eigenvectors are not the right ones, and a mode's coupling needs both.
// Ideal limit: Ek = 0 makes A Hermitian and every λ real (iC is Hermitian); with Ek > 0, Im λ = Ek x̄ᵀKx / x̄ᵀMx > 0.
//
// A partially filled tank (docs/volume.md §8): the free surface's terms and forcing directions, viscous_fill_surface.hpp;
// the stress-free surface makes K the stress form K_s = 2∫ D(V):D(W) = K + ∫ ∇V:(∇W)ᵀ, in Cartesian blocks
// K_s[d][d′] = δ_dd′ K0 + ∫ ∂_d′ w ∂_d v (test component d, field component d′).
//
// Couplings: c_k = ∫ (e_k × r)·V dτ = f_kᵀx with r measured from `centroid`:
//   f_x(V) = ∫ (−z' V_y + y' V_z),  f_y(V) = ∫ (z' V_x − x' V_z),  f_z(V) = ∫ (−y' V_x + x' V_y).
#pragma once

#include "viscous_forms.hpp"
#include "volume_taylor_hood.hpp"

#include <mpi.h>

#include <array>

namespace rc::modes {

struct ViscousVolumeForms {
  ViscousForms forms;                  // Â, M̂, i𝓜 (forms.coupling = f_x)
  std::array<PVec, 3> couplings;       // f_x, f_y, f_z on the real slots (the velocity's moment only)
  PVec velocity_slots;                 // 1 on the velocity unknowns' real slots, 0 elsewhere (J keeps their real part)
  // A partially filled tank (the space has a free surface: viscous_fill_surface.hpp): K is the stress form K_s, the
  // surface's η̃ follow the pressure, and the five directions about P0 drive the liquid as F_j and give its moment as
  // G_jᵀx (G_j = F̄_j). Empty for a full cavity.
  std::vector<PVec> fill_inputs, fill_outputs;
  std::array<double, 3> axis_point{};  // P0
  double surface_radius = 0;           // b
};

// Assembles on `comm` (each rank a contiguous share of the elements). ekman >= 0.
ViscousVolumeForms assemble_viscous_volume_forms(const VolumeTaylorHoodSpace& space, const std::array<double, 3>& centroid,
                                                 double ekman, MPI_Comm comm);

}  // namespace rc::modes
