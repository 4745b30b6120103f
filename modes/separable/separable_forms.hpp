// The 1-D forms whose Kronecker products are the Poincaré forms of a cylinder (separable_cylinder.hpp's header;
// docs/physics.md §2): shared by the separable cylinder solver and the partially filled cylinder's radial problem
// (freesurface/free_surface_cylinder.hpp).
#pragma once

#include "line_space.hpp"

#include "eigen_dense.hpp"

namespace rc::modes {

// On a partition of r (the axis dof left out when the partition starts at r = 0):
//   A = ∫ (φ_i′φ_j′ + φ_iφ_j/r²) r dr,  B = ∫ φ_iφ_j r dr,  C = ∫ (φ_i′φ_j + φ_iφ_j′) dr,
//   g1 = ∫ (rφ)′ dr,  g2 = ∫ r²φ dr (the coupling functionals' radial factors).
struct RadialForms {
  Eigen::MatrixXd A, B, C;
  Eigen::VectorXd g1, g2;
};
RadialForms radial_forms(const LineSpace& R);

// On z ∈ [−H/2, H/2]: A = ∫ ψ_i′ψ_j′ dz, B = ∫ ψ_iψ_j dz, s = ∫ (z − centroid_z)ψ dz, t = ∫ ψ′ dz.
struct AxialForms {
  Eigen::MatrixXd A, B;
  Eigen::VectorXd s, t;
};
AxialForms axial_forms(const LineSpace& Z, double centroid_z);

}  // namespace rc::modes
