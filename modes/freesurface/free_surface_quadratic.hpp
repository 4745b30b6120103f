// The mesh method's free-surface problem as one symmetric quadratic (free_surface_mesh.hpp's header derives it from
// the quartic): its forms about the liquid's centroid, its coefficients, one eigenpair's coupling, and the integrals
// every spectrum carries. Shared by the dense solver (every pair, free_surface_mesh.hpp) and the sparse one (the pairs
// near given frequencies, free_surface_sparse.hpp).
#pragma once

#include "fe_space.hpp"
#include "free_surface_forms.hpp"
#include "partial_fill_spectrum.hpp"

#include <Eigen/Sparse>

#include <array>

namespace rc::modes {

struct FreeSurfaceQuadratic {
  FluidIntegrals fluid;                // of the liquid; the forms are about its centroid
  Eigen::SparseMatrix<double> Kh, Kz, Gc, M;
  Eigen::VectorXd f1, f2;
  FreeSurfaceForms surface;
  std::array<double, 4> norms{};       // Frobenius norms of S, M + 4S, Gc, Kz: the residuals' scale

  long pressure_dofs() const { return M.rows(); }
  long unknowns() const { return M.rows() + static_cast<long>(surface.surface_dofs.size()); }
  // A0, A1, A2 of λ² A2 + λ A1 + A0 over (x, y), y one unknown per surface dof (free_surface_mesh.hpp).
  std::array<Eigen::SparseMatrix<double>, 3> coefficients() const;
};

// Assembles the volume and surface forms of the liquid meshed by `space`.
FreeSurfaceQuadratic free_surface_quadratic(const FESpace& space);

// One eigenpair (λ real, x the pressure at the dofs) with its residual in the quartic and its coupling.
PartialFillPair free_surface_pair(const FreeSurfaceQuadratic& q, double lambda, const Eigen::VectorXd& x);

// A spectrum without pairs yet: the liquid's integrals, b, K, Zhukovsky's inertia with the free surface at zero
// potential, the sum rule, the liquid's axial extent and the discretisation's sizes.
PartialFillSpectrum spectrum_integrals(const FESpace& space, const FreeSurfaceQuadratic& q);

}  // namespace rc::modes
