// The frequencies at which each body's tanks are driven in the chain's motions e^{iσt} (docs/rom.md, "Confirmed roots
// at two spins"): what a response table must be exact at for the chain's root σ to be the fluid's own.
//
// At one spin a mode's coordinate z (in its body's axes) follows the root: z ∝ e^{iσt}. At two spins the motion is a
// Floquet solution y = e^{iσt} p(t), p T-periodic (floquet.hpp), and z = e^{iσt} Σ_j z_j e^{ijνt} (ν = 2π/T) is driven
// at every σ + jν: a tank on a body that turns against the frame F is driven mostly at one shifted harmonic (its
// axisymmetric part at σ + (ω_k − ω0)), a body without axial symmetry spreads its motion over several. The harmonics
// come from the monodromy's eigenvector carried over a period by the Magnus steps the roots settled with, sampled on
// their grid (a discrete Fourier transform, exact for the harmonics below half the steps).
#pragma once

#include "general_chain.hpp"

#include <complex>
#include <ostream>
#include <vector>

namespace rc::rom {

// Harmonics whose share of the mean square of a body's fluid coordinates is below this are left out (amplitude 1e-5
// of the whole: an error ε of the table there moves the root by about 1e-10 ε of its coupling); at most kMostHarmonics
// of the largest are kept for each root.
inline constexpr double kHarmonicShare = 1e-10;
inline constexpr int kMostHarmonics = 8;

// Per body (0-based), the frequencies (rad/s, in the body's own axes) at which its tanks are driven in the motions of
// `roots` (roots of general_spectrum(g); at two spins Floquet exponents in any branch). A body without modes gets
// none. One line to `log` per root at two spins: the harmonics kept and the share left out.
std::vector<std::vector<std::complex<double>>> driven_frequencies(const GeneralChain& g,
                                                                  const std::vector<std::complex<double>>& roots,
                                                                  std::ostream& log);

}  // namespace rc::rom
