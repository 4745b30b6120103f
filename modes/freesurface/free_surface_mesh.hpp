// A partially filled tank on a meridian mesh (any built-in shape with its free surface r = b; docs/physics.md §2,
// "Partially filled cylinder: the free surface" and "Partially filled tanks: coupling to the body"): every m = 1
// eigenpair of the quartic pencil
//   −λ⁴ S + λ²(M + 4S) + 2λ Gc − 4 Kz = 0     (M = Kh + Kz, S the surface form of free_surface_forms.hpp),
// made a symmetric quadratic by one unknown per surface dof, y = λ² P x (P: the surface dofs, M_s = P S Pᵀ):
//   λ² [M + 4S, −PᵀM_s; −M_sP, 0] + λ [2Gc, 0; 0, 0] + [−4Kz, 0; 0, M_s],
// whose λ² coefficient is invertible (M is positive definite off the axis, M_s on the surface), so that every one of
// its 2(n + n_s) eigenvalues is finite; all of them, with their couplings, by a dense eigensolver (LAPACK) of the
// companion form. Complete, so that Σ E over the pairs is the sum rule A_f + K2 − J_D to rounding — the check of
// every table — but dense: meshes of at most `max_unknowns` (n + n_s) unknowns (docs/modes.md says what converges).
#pragma once

#include "fe_space.hpp"
#include "partial_fill_spectrum.hpp"

namespace rc::modes {

// Throws std::runtime_error for a mesh without a free surface or larger than max_unknowns, a failed dense solve, or
// an eigenvalue that is not real (the problem is self-adjoint with positive energy: a complex one is a defect).
// With keep_pressure every pair keeps its eigenvector (for --fields).
PartialFillSpectrum solve_partially_filled_mesh(const FESpace& space, int max_unknowns, bool keep_pressure = false);

}  // namespace rc::modes
