// The partially filled cylinder's m = 1 modes of one axial wave sin(kz) by finite elements in r: an independent
// check of the closed form (partial_fill_closed_form.hpp), from the weak form rather than from the strong boundary
// conditions (docs/physics.md §2, "Partially filled cylinder").
//
// Testing div V = 0 with q e^{iφ} over b < r < a as for the completely filled cavity, the free surface's
// u·n = −u_r = iλ p/b (kinematic iλη = u_r, dynamic p = −b η, ω0 = ρ = 1) leaves the boundary term iλ ∫ q p dz at
// r = b, so that the quadratic pencil gains a quartic term:
//   −λ⁴ S + λ²(K_h + K_z + 4S) + 2λ G_c − 4 K_z = 0,   S = ∫_{r=b} q p dz.
// With p = x(r) sin(kz) this is, per axial wave, λ⁴ P4 + λ² P2 + λ P1 + P0 = 0 with P4 = −e eᵀ (e: the basis
// functions' values at r = b), P2 = A + k²B + 4 e eᵀ, P1 = 2C, P0 = −4k²B (separable_forms.hpp), solved completely by
// its companion linearisation (dense; P4 is singular, so most of its eigenvalues are infinite and left out).
#pragma once

#include <vector>

namespace rc::modes {

// The finite eigenvalues λ of the radial quartic on `elements` uniform elements of order `order` over [b, a] (the
// ones at each end cut into two corner layers), sorted ascending. Throws std::invalid_argument for 0 < b < a not
// holding, std::runtime_error when the dense eigensolver fails or a finite eigenvalue is not real (|Im λ| above 1e-8
// of |λ|: the problem is self-adjoint with positive energy, so that would be a defect).
std::vector<double> free_surface_radial_eigenvalues(double a, double b, double k, int order, int elements);

}  // namespace rc::modes
