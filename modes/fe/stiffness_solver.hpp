// A sparse symmetric factorisation (MUMPS) factorised once and reused, on the matrix's communicator. For M = Kh + Kz, the m = 1 Laplacian
// stiffness (positive definite: Cholesky), by the Zhukovsky potential and by every step of the spectral
// survey's projection; for the indefinite Q(σ) of the shift-invert survey (MUMPS LDLᵀ with pivoting).
#pragma once

#include "petsc_handles.hpp"

#include <string>
#include <vector>

namespace rc::modes {

class StiffnessSolver {
 public:
  // prefix: PETSc options prefix of the KSP (so that users can tune either factorisation); name: what the
  // matrix is, for error messages.
  explicit StiffnessSolver(Mat M, const char* prefix = "stiff_", std::string name = "the stiffness matrix");
  // x = M⁻¹ b. Throws if the solve fails.
  void solve(Vec b, Vec x) const;
  // On plain arrays of length ndof held whole by every rank: each rank hands in its rows of b and receives the whole
  // x (a distributed M — MUMPS's factors split between the ranks — under callers whose vectors are replicated).
  void solve(const std::vector<double>& b, std::vector<double>& x) const;

 private:
  std::string name_;
  PKSP ksp_;
  PVec b_, x_, x_all_;
  PVecScatter to_all_;
};

}  // namespace rc::modes
