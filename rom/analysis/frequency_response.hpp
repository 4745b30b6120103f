// The chain's frequency response: each body's tilt per unit harmonic moment on one body, from the characteristic
// matrix of Kononov (22)/(29) itself, so exact for ideal, damped-mode and response-fit tanks alike.
//
// A moment F e^{iσt} on body K (complex, in the convention of the tilts u_k = β_k − iα_k) enters (26) on body K's
// row; with u = û e^{iσt} the system becomes Z(σ) û = F e_K with the dynamic stiffness
//   Z(σ) = −σ² Φ(σ) = −σ² (M − diag(fluid_k(σ))) − σ diag(C_k ω_k0) + iσ D + K,
//   fluid_k(σ) = Σ_l (σ + ω_k0) E_kl/(σ + ω_k0 − λ_kl) + E_rem,k                    (characteristic.hpp),
// written out so that σ = 0 (the static response K û = F) needs no limit. Z is singular at the roots: the
// resonances, whose real parts inside the range are reported with the curve.
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"
#include <complex>
#include <vector>

namespace rc::rom {

struct FrequencyResponse {
  int body = 0;                         // 0-based: the body the moment acts on
  std::vector<double> sigma;            // rad/s, the moment's frequency (e^{iσt}; σ < 0: the other sense of turning)
  Eigen::MatrixXcd tilt;                // sigma.size() × n: û_j per unit moment (rad per N m); NaN where Z is singular
  std::vector<double> resonances;       // Re σ of the chain's roots inside [sigma.front(), sigma.back()]
  std::vector<double> resonance_growth; // their −Im σ (1/s): how sharp (near 0) and whether growing (> 0)
  int singular = 0;                     // frequencies where Z(σ) could not be solved (exactly at a root or a pole)
};

Eigen::MatrixXcd dynamic_stiffness(const ChainModel& m, std::complex<double> sigma);

// `steps` >= 2 frequencies from `from` to `to`; the roots come from the first-order system's eigenvalues.
FrequencyResponse frequency_response(const ChainModel& m, int body, double from, double to, int steps);

}  // namespace rc::rom
