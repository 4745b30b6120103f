// Damped modes of the viscous fluid in a 3-D cavity near a complex target, with their coupling tensors
// (docs/volume.md §7). The pencil is not symmetric (viscous_volume_forms.hpp), so a mode's response residue takes its
// right eigenvector x and its left one y (Aᵀy = λ𝓜y, normalised yᵀ𝓜x = 1):
//   H_jk = (f_jᵀ x)(f_kᵀ y),
// the fluid's moment about e_j per unit rotation rate about e_k carried by the mode. In the ideal limit y = x̄ and H
// is the Hermitian c cᴴ / ‖V‖² of the ideal 3-D table (docs/volume.md §1); an axisymmetric cavity's m = 1 mode has
// H_xx + H_yy = E, the meridian viscous table's complex coupling.
#pragma once

#include "viscous_volume_forms.hpp"

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace rc::modes {

struct DampedVolumeMode {
  std::complex<double> lambda;  // e^{iλt}: Re λ the frequency in the rotating frame, Im λ > 0 the decay rate
  Eigen::Matrix3cd H;           // the coupling tensor above, in the spin frame
  double residual = 0;          // ‖Ax − λ𝓜x‖ / (|λ| ‖x‖)
  double left_residual = 0;     // ‖Aᵀy − λ𝓜y‖ / (|λ| ‖y‖)
};

// The damped modes nearest `target` (at most `pairs`), sorted by distance from it. Throws std::runtime_error when the
// solver fails (viscous_eigensolver.hpp) or a left eigenvector does not converge.
std::vector<DampedVolumeMode> damped_volume_modes(const ViscousVolumeForms& forms, std::complex<double> target, int pairs);

}  // namespace rc::modes
