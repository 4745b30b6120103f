// A sparse Cholesky factorisation (MUMPS) of M = Kh + Kz, the m = 1 Laplacian stiffness, factorised once
// and reused: by the Zhukovsky potential and by every step of the spectral survey's projection.
#pragma once

#include "petsc_handles.hpp"

#include <vector>

namespace rc::modes {

class StiffnessSolver {
 public:
  explicit StiffnessSolver(Mat M);
  // x = M⁻¹ b. Throws if the solve fails.
  void solve(Vec b, Vec x) const;
  // Convenience overload on plain arrays of length ndof.
  void solve(const std::vector<double>& b, std::vector<double>& x) const;

 private:
  PKSP ksp_;
  PVec b_, x_;
};

}  // namespace rc::modes
