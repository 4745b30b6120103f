// Passivity of a fluid's response written as a modal sum, R(s) = sum_l E_l/(s - lambda_l) (docs/physics.md §2; a
// viscous table's damped modes or a response fit's poles, docs/viscous.md): the fluid only takes energy from a
// harmonic motion, so on the real axis Im R(s) >= 0. A response fit keeps that only to its accuracy; cavity-modes
// reports the scan when it writes a fit, chain-rom's `spectrum` when it reads one (docs/rom.md, "Viscous tanks").
#pragma once

#include <complex>
#include <vector>

namespace rc {

struct PassivityScan {
  double min_im = 0;   // min over the window of Im R(s) / max |R(s)|
  double at = 0;       // where
  bool passive() const { return min_im >= 0; }
};

// Im R on [lo, hi]: 2001 points, and 81 more about each pole on the window, a quarter of its decay apart (R varies on
// that scale there). Poles in the upper half plane (lambda = lambda_r + i decay, decay > 0).
PassivityScan scan_passivity(const std::vector<std::complex<double>>& poles,
                             const std::vector<std::complex<double>>& residues, double lo, double hi);

}  // namespace rc
