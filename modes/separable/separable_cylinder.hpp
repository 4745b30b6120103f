// The circular cylinder's Poincaré problem separated at the discrete level (docs/modes.md, "Separable
// cylinder solver").
//
// On a tensor-product grid of 1-D Lagrange elements (r: 0..a with p = 0 on the axis, or b..a for an annular
// cylinder around a coaxial rod of radius b, whose inner wall is a wall like the outer one; z over the height),
// the forms of docs/physics.md §2 are Kronecker products of 1-D forms:
//   Kh = Ar ⊗ Bz,  Kz = Br ⊗ Az,  Gc = Cr ⊗ Bz,
//   Ar = ∫ (φ_i′φ_j′ + φ_iφ_j/r²) r dr,  Br = ∫ φ_iφ_j r dr,  Cr = ∫ (φ_i′φ_j + φ_iφ_j′) dr,
//   Az = ∫ ψ_i′ψ_j′ dz,  Bz = ∫ ψ_iψ_j dz,
// and the coupling functionals f1 = g1 ⊗ s, f2 = g2 ⊗ t with g1 = ∫ (rφ)′ dr, g2 = ∫ r²φ dr, s = ∫ z′ψ dz,
// t = ∫ ψ′ dz (z′ from the centroid). In the Bz-orthonormal eigenbasis of Az w_n = μ_n Bz w_n (fast
// diagonalisation, Lynch–Rice–Thomas 1964) the 2-D quadratic eigenproblem splits EXACTLY into one radial
// problem per axial vector:
//   λ² (Ar + μ_n Br) x + 2λ Cr x − 4μ_n Br x = 0,   p = x ⊗ w_n,
// which is hyperbolic with a negative definite constant term, so its linearisation
//   [−2Cr 4μBr; 4μBr 0] z = λ [Ar + μBr 0; 0 4μBr] z,   z = (λx, x),
// is a symmetric-definite pencil: every eigenpair, real, by a dense solver. No eigenpair of different axial
// vectors mixes, so an exact mode's E is not spread over copies: each discrete eigenpair is one mode.
// Zhukovsky's problem (docs/physics.md §2) splits the same way: (Ar + μ_n Br) χ_n = g1 s_n − g2 t_n.
#pragma once

#include "poincare_forms.hpp"

#include <functional>
#include <vector>

namespace rc::modes {

// Element breaks of the two factor spaces and their order.
struct SeparableGrid {
  int order = 8;
  double inner_radius = 0;     // > 0: the annular cylinder inner_radius < r < radius (no axis)
  std::vector<double> radial;  // on [inner_radius, radius], increasing
  std::vector<double> axial;   // on [−height/2, height/2], increasing; symmetric about 0 (even modes then decouple)

  // Uniform elements, the one at each wall (r = radius, and r = inner_radius when positive) and the one at each lid
  // further cut into corner_layers + 1 pieces halving towards the corner (graded_breaks, line_space.hpp).
  // axial_elements >= 2.
  static SeparableGrid graded(double radius, double height, int order, int radial_elements, int axial_elements,
                              int corner_layers, double inner_radius = 0);
  int radial_elements() const { return static_cast<int>(radial.size()) - 1; }
  int axial_elements() const { return static_cast<int>(axial.size()) - 1; }
};

struct SeparableMode {
  double lambda = 0, E = 0;
  double residual = 0;  // backward error of (λ, x) for the radial QEP: ‖Q(λ)x‖ / ((λ²‖M‖ + 2|λ|‖Cr‖ + 4μ‖Br‖)‖x‖)
  int axial = 0;        // n: rank of the axial eigenvector among the coupled ones, μ ascending (0-based):
                        //    Stewartson's k = (2n + 1)π/(2h) for a resolved mode
  int radial = 0;       // j: rank of |λ| (descending) among the same axial vector's eigenvalues of the same sign,
                        //    1-based (Stewartson's root index); 0 for the E = 0 null eigenvalue λ = −2
};

struct SeparableSpectrum {
  FluidIntegrals fluid;
  double J_zh = 0;
  double sum_rule = 0;          // A_f − J_zh
  double sum_E = 0;             // Σ E over every eigenpair: equals sum_rule (docs/physics.md §2) up to rounding
  long ndof = 0;                // radial × axial dofs of the 2-D tensor space
  int radial_dofs = 0, axial_dofs = 0;
  int coupled_axial = 0;        // axial vectors with a non-zero coupling projection (each solved)
  std::vector<SeparableMode> modes;  // every eigenpair of every coupled axial vector, E descending
};

// The cavity is the cylinder (grid.inner_radius = 0) or the annular cylinder grid.inner_radius < r < radius.
// Throws std::invalid_argument for non-positive or non-finite dimensions or a grid that does not span them, and
// std::runtime_error if a dense factorisation fails.
// progress(done, total) is called from the calling thread as the radial problems finish.
using SeparableProgress = std::function<void(int done, int total)>;
SeparableSpectrum solve_separable_cylinder(double radius, double height, const SeparableGrid& grid,
                                           const SeparableProgress& progress = {});

}  // namespace rc::modes
