// The frequency response of the chain without axial symmetry (docs/rom.md, "Frequency response"): each body's tilt per
// unit harmonic moment on one body, as `chain-rom response` gives for (26), from the first-order form of
// general_system.hpp.
//
// A moment F e^{iσt} on body K in (26)'s convention (u = β − iα, the inertial frame) is F e^{iΩt}, Ω = σ + ω0, on the
// complex tilt v = q_x − i q_y of the frame turning at ω0 (u = e^{−iω0t} v), whose real rows (Re, −Im) take the force
// Re[e^{iΩt} F (1, i)]. With the steady response q(t) = Re[e^{iΩt} q̂], v = A₊ e^{iΩt} + A₋ e^{−iΩt} with
//   A₊ = (q̂_x − i q̂_y)/2,   A₋ = conj(q̂_x + i q̂_y)/2,
// so that in the inertial frame u = A₊ e^{iσt} + A₋ e^{−i(σ + 2ω0)t}: A₊ is (26)'s tilt û (an axisymmetric chain has
// A₋ = 0), A₋ the mirror tilt that a body or tank without axial symmetry adds at the frequency −σ − 2ω0.
#pragma once

#include "general_chain.hpp"

#include "eigen_dense.hpp"

#include <vector>

namespace rc::rom {

struct GeneralFrequencyResponse {
  int body = 0;                      // 0-based: the body the moment acts on
  std::vector<double> sigma;         // rad/s, the moment's frequency in the inertial frame
  Eigen::MatrixXcd tilt;             // sigma.size() × n: A₊ per unit moment (rad per N m); NaN where singular
  Eigen::MatrixXcd mirror;           // sigma.size() × n: A₋ per unit moment, at the frequency −σ − 2ω0
  Eigen::MatrixXd sideband;          // at two spins (periodic_response.hpp): sigma.size() × n, the root mean square
                                     // tilt at every other frequency per unit moment; empty at one spin
  int steps_per_period = 0;          // at two spins: the Magnus steps a period (at the largest |σ + ω0|)
  std::vector<double> resonances;    // σ = Re σ_F − ω0 of the chain's roots σ_F (turning frame) inside the range
  std::vector<double> resonance_growth;  // their −Im σ_F (1/s)
  int singular = 0;                  // frequencies where iΩ − B could not be solved
};

// `steps` >= 2 frequencies from `from` to `to`; a periodic chain's through periodic_response.hpp. Throws
// std::runtime_error as build_general_system.
GeneralFrequencyResponse general_frequency_response(const GeneralChain& g, int body, double from, double to,
                                                    int steps);

// The resonances and their growth from the chain's roots (at two spins the Floquet roots in the branch of the
// period-averaged chain's).
void mark_resonances(const GeneralChain& g, double from, double to, GeneralFrequencyResponse& r);

}  // namespace rc::rom
