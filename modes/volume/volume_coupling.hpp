// A 3-D mode's coupling from its pressure (docs/volume.md §1): with V from P by
//   V_h = −(iλ − 2ẑ×)∇_h P / (4 − λ²),   V_z = (i/λ) P_z   (ω0 = 1),
// c_k = ∫ (e_k × r)·V dτ (r from the fluid centroid) and ‖V‖² = ∫ |V|² dτ, by quadrature. H = c cᴴ / ‖V‖² is the
// mode's coupling tensor, unchanged by any complex scaling of P: the check of the block Lanczos survey's tensors
// (volume_survey.hpp) by an independent route.
#pragma once

#include "volume_space.hpp"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <vector>

namespace rc::modes {

struct PressureModeCoupling {
  Eigen::Vector3cd c = Eigen::Vector3cd::Zero();
  double norm2 = 0;
  Eigen::Matrix3cd tensor() const { return c * c.adjoint() / norm2; }
};

// V of a mode at λ from its pressure gradient g = ∇P, by the formula above (λ ≠ 0, |λ| ≠ 2).
inline Eigen::Vector3cd velocity_from_pressure_gradient(double lambda, const Eigen::Vector3cd& g) {
  const std::complex<double> i(0, 1);
  const double D = 4 - lambda * lambda;
  // (iλ − 2ẑ×) g_h with ẑ × (g_x, g_y) = (−g_y, g_x).
  return {-(i * lambda * g(0) + 2.0 * g(1)) / D, -(i * lambda * g(1) - 2.0 * g(0)) / D, i * g(2) / lambda};
}

// p: the real form (P_r at the dofs, then P_i), as QuadraticEigenSolver returns it; λ ≠ 0, |λ| ≠ 2.
PressureModeCoupling pressure_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            double lambda, const std::vector<double>& p);

// The same for a superposition Σ weight_l V_l of modes at different λ_l (the field of a table row whose modes are
// discrete copies: modes/volume/volume_fields.hpp).
struct PressureMember {
  double lambda = 0;
  const std::vector<double>* p = nullptr;  // real form, as above
  std::complex<double> weight = 1.0;
};
PressureModeCoupling combined_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            const std::vector<PressureMember>& members);

}  // namespace rc::modes
