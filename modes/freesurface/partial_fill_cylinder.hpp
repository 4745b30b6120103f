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

#include "free_surface_coupling.hpp"
#include "poincare_forms.hpp"
#include "separable_cylinder.hpp"

#include <vector>

namespace rc::modes {

struct PartialFillPair {
  double lambda = 0;
  FreeSurfaceCoupling coupling;  // about the liquid's centroid (a, E) and per unit offset (t)
  double residual = 0;           // ‖Q(λ)x‖ / ((λ⁴‖S‖ + λ²‖Ar + μBr + 4S‖ + 2|λ|‖Cr‖ + 4μ‖Br‖)‖x‖)
  int axial = 0;                 // rank of the axial vector, μ ascending (0-based)
};

struct PartialFillSpectrum {
  double surface_radius = 0;  // b
  FluidIntegrals fluid;       // of the liquid annulus
  double K0 = 0, K1 = 0, K2 = 0;  // π b² ∫ z′ᵏ dz over the free surface: K(O) = K2 + 2c K1 + c² K0
  // Zhukovsky's inertia with the free surface at zero potential, about a point O at height −c below the centroid:
  // J_D(c) = J_D + 2c J_D1 + c² J_D2 (the potential problem's data is linear in c).
  double J_D = 0, J_D1 = 0, J_D2 = 0;
  double sum_rule = 0;        // A_f + K2 − J_D: what Σ E over every pair must give
  double sum_E = 0;           // Σ E over every pair
  int radial_dofs = 0, axial_dofs = 0;
  int order = 0, radial_elements = 0, axial_elements = 0;
  std::vector<PartialFillPair> pairs;  // every eigenpair of every coupled axial vector, E descending

  double zhukovsky_about(double c) const { return J_D + 2 * c * J_D1 + c * c * J_D2; }
  // A_f(O) + K(O) − J_D(O): the sum over every pair of coupling_about(pair, c).
  double sum_rule_about(double c) const {
    return fluid.A_f + fluid.volume * c * c + K2 + 2 * c * K1 + c * c * K0 - zhukovsky_about(c);
  }
};

// The liquid fills the fraction `fill` (0 < fill < 1) of the cylinder of radius `radius` and height `height`;
// the grid's radial breaks must span [b, radius] with b = radius √(1 − fill). Throws std::invalid_argument for bad
// dimensions or a grid that does not span the annulus, std::runtime_error if a dense solver fails or an eigenvalue
// is not real.
PartialFillSpectrum solve_partially_filled_cylinder(double radius, double height, double fill,
                                                    const SeparableGrid& grid);

}  // namespace rc::modes
