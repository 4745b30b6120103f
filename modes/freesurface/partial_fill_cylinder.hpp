// The partially filled cylinder separated at the discrete level: every m = 1 eigenpair of the liquid annulus
// b < r < a, |z| < h with its free surface r = b, and its coupling to the body (docs/physics.md §2, "Partially
// filled tanks"). The reference for the free surface's coupling, as separable_cylinder.hpp is for the filled
// cylinder.
//
// On a tensor-product grid (SeparableGrid, r over [b, a], z over the height) the forms are Kronecker products and
// the surface form is S = e eᵀ ⊗ Bz (e: the radial basis functions' values at r = b). In the Bz-orthonormal
// eigenbasis of Az (Az w = μ Bz w) the problem splits into one radial quartic per axial vector,
//   −λ⁴ S_r x + λ²(Ar + μ Br + 4 S_r) x + 2λ Cr x − 4μ Br x = 0,   S_r = e eᵀ,
// made a symmetric quadratic by the one surface unknown y = λ² eᵀx:
//   λ² [Ar + μBr + 4S_r, −e; −eᵀ, 0] + λ [2Cr, 0; 0, 0] + [−4μBr, 0; 0, 1],
// whose λ² coefficient is invertible (so every one of its 2(n + 1) eigenvalues is finite), solved completely by a
// dense eigensolver of its companion form. The problem is self-adjoint with positive energy, so the eigenvalues are
// real; a complex one is reported as a defect.
#pragma once

#include "partial_fill_spectrum.hpp"
#include "separable_cylinder.hpp"

#include <vector>

namespace rc::modes {

// The liquid fills the fraction `fill` (0 < fill < 1) of the cylinder of radius `radius` and height `height`;
// the grid's radial breaks must span [b, radius] with b = radius √(1 − fill). Throws std::invalid_argument for bad
// dimensions or a grid that does not span the annulus, std::runtime_error if a dense solver fails or an eigenvalue
// is not real.
PartialFillSpectrum solve_partially_filled_cylinder(double radius, double height, double fill,
                                                    const SeparableGrid& grid);

}  // namespace rc::modes
