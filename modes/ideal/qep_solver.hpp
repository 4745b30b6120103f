// The quadratic eigenproblem λ² M + 2λ Gc − 4 Kz = 0 (docs/physics.md §2, m = 1, ω0 = 1) with SLEPc PEP.
//
// The problem is real symmetric and hyperbolic (M > 0, Kz ≥ 0), so every eigenvalue is real and STOAR
// with spectrum slicing finds ALL eigenvalues in an interval [lo, hi]: shift-and-invert steps with a
// sparse LDLᵀ factorisation (MUMPS) whose inertia counts the eigenvalues left of each shift, so nothing in
// the interval can be missed. E of each eigenpair is computed on the fly; eigenvectors are kept only when
// asked for (QepSettings::keep_eigenvectors: the fields of cavity-modes --fields).
#pragma once

#include "coupling.hpp"
#include "poincare_forms.hpp"

#include <array>
#include <string>
#include <vector>

namespace rc::modes {

struct Eigenpair {
  double lambda = 0;
  ModeCoupling coupling;
  double residual = 0;   // backward error ‖Q(λ)x‖ / ((|λ|²‖M‖ + |λ|‖2Gc‖ + ‖4Kz‖)‖x‖)
  std::vector<double> p;  // the eigenvector (p at the dofs, SLEPc's scale), only with keep_eigenvectors
};

struct QepSettings {
  double tolerance = 1e-12;
  int max_iterations = 0;  // 0: SLEPc's default
  bool keep_eigenvectors = false;
};

struct QepSolution {
  std::vector<Eigenpair> pairs;  // sorted by λ ascending
};

class QuadraticEigenSolver {
 public:
  QuadraticEigenSolver(const PoincareForms& forms, const QepSettings& settings);
  // All eigenpairs with lo <= λ <= hi. Throws on solver failure or if SLEPc did not converge.
  QepSolution solve_interval(double lo, double hi) const;
  // Every one of the 2·ndof eigenpairs, by a dense solve of the linearisation (SLEPc PEPLINEAR + LAPACK).
  // For small meshes only (validation of the sum rule); throws above max_dense_dofs.
  QepSolution solve_all_dense(int max_dense_dofs = 2000) const;

 private:
  const PoincareForms& forms_;
  QepSettings settings_;
  std::array<PMat, 3> coefficients_;  // A0 + λ A1 + λ² A2
  CouplingEvaluator coupling_;
  QepSolution collect(PEP pep) const;
};

}  // namespace rc::modes
