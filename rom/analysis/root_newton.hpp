// The second, independent root finder of `chain-rom spectrum`: Newton's method on det Phi(sigma) = 0, the
// characteristic equation (22)/(29) of Kononov itself (characteristic.hpp), where the eigen-solver works
// on the first-order matrix of (26). With f = det Phi, f'/f = tr(Phi^{-1} Phi'), so a Newton step is
//   sigma <- sigma - 1 / tr(Phi(sigma)^{-1} Phi'(sigma)).
// Started from an eigen-root it converges to the root of (22) nearest it; the distance between the two
// is the cross-check reported for every root (docs/rom.md, "Spectrum", second root finder).
#pragma once

#include "chain_model.hpp"

#include <complex>

namespace rc::rom {

struct NewtonRoot {
  std::complex<double> sigma;  // the root of det Phi = 0 Newton reached
  int iterations = 0;
  bool converged = false;      // last step below 1e-14 of the scale (or Phi exactly singular)
};

// Newton on det Phi from sigma0; `scale` is a typical |sigma| (steps are judged against it).
// Not converged after 50 steps, or stepping onto sigma = 0 or a pole: converged = false.
NewtonRoot newton_root(const ChainModel& m, std::complex<double> sigma0, double scale);

}  // namespace rc::rom
