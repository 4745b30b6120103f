// The free surface's forms on a meridian mesh (docs/physics.md §2, "Partially filled cylinder: the free surface",
// item 4, and "Partially filled tanks: coupling to the body", item 9), beside the volume forms of poincare_forms.hpp,
// as Eigen sparse matrices and vectors (z′ = z − z_c from the liquid's centroid, r = b on the surface):
//   S(q, p) = ∫_{r=b} q p dz,   f3(q) = b ∫_{r=b} z′ q dz,   e1(q) = b ∫_{r=b} q dz,   g1(q) = ∫∫ (r q)_r dr dz,
// and the surface's re-centring inertia K_k = π b² ∫_{r=b} z′ᵏ dz (k = 0, 1, 2).
#pragma once

#include "fe_space.hpp"
#include "petsc_handles.hpp"

#include <Eigen/Sparse>

#include <vector>

namespace rc::modes {

struct FreeSurfaceForms {
  double radius = 0;                 // b
  Eigen::SparseMatrix<double> S;     // ndof × ndof, nonzero on the surface's dofs only
  Eigen::VectorXd f3, e1, g1;
  std::vector<int> surface_dofs;     // the dofs on r = b, ascending
  double K0 = 0, K1 = 0, K2 = 0;
};

// Throws std::runtime_error if the mesh has no free surface.
FreeSurfaceForms assemble_free_surface_forms(const FESpace& space, double centroid_z);

// A PETSc sequential matrix or vector as Eigen's (the volume forms of poincare_forms.hpp).
Eigen::SparseMatrix<double> to_eigen(Mat A);
Eigen::VectorXd to_eigen(Vec v);

}  // namespace rc::modes
