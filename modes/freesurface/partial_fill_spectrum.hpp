// Every eigenpair of a partially filled tank with its coupling to the body, and the integrals its table needs
// (docs/physics.md §2, "Partially filled tanks: coupling to the body"): what the separable cylinder
// (partial_fill_cylinder.hpp) and the mesh method (free_surface_mesh.hpp) both return.
#pragma once

#include "free_surface_coupling.hpp"
#include "poincare_forms.hpp"

#include <vector>

namespace rc::modes {

struct PartialFillPair {
  double lambda = 0;
  FreeSurfaceCoupling coupling;  // about the liquid's centroid (a, E) and per unit offset (t)
  double residual = 0;           // ‖Q(λ)x‖ / ((λ⁴‖S‖ + λ²‖Ar + μBr + 4S‖ + 2|λ|‖Cr‖ + 4μ‖Br‖)‖x‖)
  int axial = 0;                 // rank of the axial vector, μ ascending (0-based); 0 for the mesh method
  std::vector<double> pressure;  // mesh method, when asked for: the eigenvector p at the pressure dofs
};

struct PartialFillSpectrum {
  double surface_radius = 0;  // b
  double height = 0;          // the liquid's axial extent (the mesh method's; a section's selection scale)
  FluidIntegrals fluid;       // of the liquid annulus
  double K0 = 0, K1 = 0, K2 = 0;  // π b² ∫ z′ᵏ dz over the free surface: K(O) = K2 + 2c K1 + c² K0
  // Zhukovsky's inertia with the free surface at zero potential, about a point O at height −c below the centroid:
  // J_D(c) = J_D + 2c J_D1 + c² J_D2 (the potential problem's data is linear in c).
  double J_D = 0, J_D1 = 0, J_D2 = 0;
  double sum_rule = 0;        // A_f + K2 − J_D: what Σ E over every pair must give
  double sum_E = 0;           // Σ E over every pair (over the pairs found when not complete)
  bool complete = true;       // every eigenpair (the dense and separable solvers); false: the sparse solver's
  int skipped = 0;            // sparse: near-double eigenvalues returned as complex pairs, not kept
  int short_targets = 0;      // sparse: targets where fewer pairs than asked converged (the nearest ones stand)
  int radial_dofs = 0, axial_dofs = 0;
  int order = 0, radial_elements = 0, axial_elements = 0;
  std::vector<PartialFillPair> pairs;  // every eigenpair of every coupled axial vector, E descending

  double zhukovsky_about(double c) const { return J_D + 2 * c * J_D1 + c * c * J_D2; }
  // A_f(O) + K(O) − J_D(O): the sum over every pair of coupling_about(pair, c).
  double sum_rule_about(double c) const {
    return fluid.A_f + fluid.volume * c * c + K2 + 2 * c * K1 + c * c * K0 - zhukovsky_about(c);
  }
};

}  // namespace rc::modes
