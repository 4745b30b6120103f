// The exact discrete spectral weight Σ E of EVERY eigenpair with λ in a window [lo, hi), by SLEPc spectrum
// slicing (no Gauss rule). A table's /bands come from the survey's Gauss rule, whose band weights are only as
// sharp as its node spacing; this separates the two errors (docs/cones.md, docs/trust.md).
#pragma once

#include "qep_solver.hpp"

#include <cstddef>

namespace rc::modes {

struct WindowWeight {
  double lo = 0, hi = 0;
  std::size_t pairs = 0;     // eigenpairs in the window
  double E = 0;              // Σ E over them
  double lambda_mean = 0;    // E-weighted mean λ (0 if E = 0)
  double E_max = 0;          // the heaviest pair's E and λ
  double lambda_of_E_max = 0;
};

// Throws std::runtime_error unless −2 < lo < hi < 2.
WindowWeight weigh_window(const QuadraticEigenSolver& solver, double lo, double hi);

}  // namespace rc::modes
