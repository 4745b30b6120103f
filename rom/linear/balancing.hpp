// Diagonal balancing of a square matrix (Parlett & Reinsch 1969; LAPACK's xGEBAL without the
// permutation step): B' = S^{-1} B S with S = diag(powers of 2) chosen so that every row and its
// column have comparable 1-norms. Eigenvalues are unchanged and, because the factors are powers of
// two, B' carries no extra rounding; eigenvectors of B are S times those of B'. The first-order matrix
// of a chain is badly scaled (its 1-norm is ~20x its spectral radius on the default scene: fluid rows
// carry lambda ~ omega, the body rows M_eff^{-1} Gamma); an eigen-solver's error is ~eps |B|, so
// balancing first makes the roots, and exact propagation over many periods, that much more accurate.
#pragma once

#include "eigen_dense.hpp"

#include <cmath>

namespace rc::rom {

// Balances B in place; returns the diagonal of S.
template <class Matrix>
Eigen::VectorXd balance_in_place(Matrix& B) {
  const Eigen::Index n = B.rows();
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(n);
  for (int sweep = 0; sweep < 100; ++sweep) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      double c = 0, r = 0;  // off-diagonal 1-norms of column i and row i
      for (Eigen::Index j = 0; j < n; ++j)
        if (j != i) {
          c += static_cast<double>(std::abs(B(j, i)));
          r += static_cast<double>(std::abs(B(i, j)));
        }
      if (c == 0 || r == 0 || !std::isfinite(c) || !std::isfinite(r)) continue;
      const double s = c + r;
      double f = 1;
      // At most 2^64 per sweep: norms near the ends of the double range (subnormal or huge) would otherwise
      // take thousands of slow steps, and the 100 sweeps still reach any scale a double can hold.
      for (int k = 0; k < 64 && c < r / 2; ++k) { f *= 2; c *= 4; }
      for (int k = 0; k < 64 && c > r * 2; ++k) { f /= 2; c /= 4; }
      if ((c + r) / f < 0.95 * s) {  // worth it: the row + column norm drops by 5 % or more
        changed = true;
        scale[i] *= f;
        B.row(i) /= f;
        B.col(i) *= f;
      }
    }
    if (!changed) break;
  }
  return scale;
}

}  // namespace rc::rom
