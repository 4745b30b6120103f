// A 3-D mode's coupling from its pressure (docs/volume.md §1): with V from P by
//   V_h = −(iλ − 2ẑ×)∇_h P / (4 − λ²),   V_z = (i/λ) P_z   (ω0 = 1),
// c_k = ∫ (e_k × r)·V dτ (r from the fluid centroid) and ‖V‖² = ∫ |V|² dτ, by quadrature. H = c cᴴ / ‖V‖² is the
// mode's coupling tensor, unchanged by any complex scaling of P: the check of the block Lanczos survey's tensors
// (volume_survey.hpp) by an independent route.
#pragma once

#include "volume_space.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace rc::modes {

struct PressureModeCoupling {
  Eigen::Vector3cd c = Eigen::Vector3cd::Zero();
  double norm2 = 0;
  Eigen::Matrix3cd tensor() const { return c * c.adjoint() / norm2; }
};

// p: the real form (P_r at the dofs, then P_i), as QuadraticEigenSolver returns it; λ ≠ 0, |λ| ≠ 2.
PressureModeCoupling pressure_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            double lambda, const std::vector<double>& p);

}  // namespace rc::modes
