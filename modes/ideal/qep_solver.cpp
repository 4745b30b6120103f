#include "qep_solver.hpp"

#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rc::modes {
namespace {

// A0 + λ A1 + λ² A2 with A0 = −4 Kz, A1 = 2 Gc, A2 = M = Kh + Kz.
std::array<PMat, 3> polynomial_coefficients(const PoincareForms& F) {
  std::array<PMat, 3> A;
  petsc_check(MatDuplicate(F.Kz, MAT_COPY_VALUES, A[0].out()), "MatDuplicate");
  petsc_check(MatScale(A[0], -4.0), "MatScale");
  petsc_check(MatDuplicate(F.Gc, MAT_COPY_VALUES, A[1].out()), "MatDuplicate");
  petsc_check(MatScale(A[1], 2.0), "MatScale");
  petsc_check(MatDuplicate(F.M, MAT_COPY_VALUES, A[2].out()), "MatDuplicate");
  return A;
}

void configure_slicing(PEP pep, double lo, double hi) {
  petsc_check(PEPSetProblemType(pep, PEP_HYPERBOLIC), "PEPSetProblemType");
  petsc_check(PEPSetType(pep, PEPSTOAR), "PEPSetType");
  petsc_check(PEPSetWhichEigenpairs(pep, PEP_ALL), "PEPSetWhichEigenpairs");
  petsc_check(PEPSetInterval(pep, lo, hi), "PEPSetInterval");
  pep_shift_invert_mumps(pep, PCCHOLESKY);
  // MUMPS must compute the inertia of the factorised matrix: no ScaLAPACK root node (ICNTL(13) = 1).
  petsc_check(PetscOptionsInsertString(nullptr, "-mat_mumps_icntl_13 1"), "PetscOptionsInsertString");
}

// A slice can take long on a fine mesh: each iteration lets the run's progress line come (progress.hpp).
PetscErrorCode tick_monitor(PEP, PetscInt, PetscInt, PetscScalar*, PetscScalar*, PetscReal*, PetscInt, void*) {
  progress_tick();
  return 0;
}

}  // namespace

QuadraticEigenSolver::QuadraticEigenSolver(const PoincareForms& forms, const QepSettings& settings)
    : forms_(forms), settings_(settings), coefficients_(polynomial_coefficients(forms)), coupling_(forms) {}

QepSolution QuadraticEigenSolver::solve_interval(double lo, double hi) const {
  const auto& settings = settings_;
  Mat mats[3] = {coefficients_[0], coefficients_[1], coefficients_[2]};
  PPEP pep;
  petsc_check(PEPCreate(PETSC_COMM_SELF, pep.out()), "PEPCreate");
  petsc_check(PEPSetOperators(pep, 3, mats), "PEPSetOperators");
  configure_slicing(pep, lo, hi);
  petsc_check(PEPSetTolerances(pep, settings.tolerance, settings.max_iterations > 0 ? settings.max_iterations
                                                                                   : PETSC_DEFAULT),
              "PEPSetTolerances");
  petsc_check(PEPSetFromOptions(pep), "PEPSetFromOptions");
  petsc_check(PEPMonitorSet(pep, tick_monitor, nullptr, nullptr), "PEPMonitorSet");
  char where[96];
  std::snprintf(where, sizeof where, "eigensolver failed on the slice [%.6g, %.6g]", lo, hi);
  petsc_check(PEPSolve(pep), where);

  QepSolution sol = collect(pep);
  return sol;
}

QepSolution QuadraticEigenSolver::collect(PEP pep) const {
  const auto& forms = forms_;
  PEPConvergedReason reason;
  petsc_check(PEPGetConvergedReason(pep, &reason), "PEPGetConvergedReason");
  if (reason < 0)
    throw std::runtime_error("the eigensolver did not converge (SLEPc reason " +
                             std::to_string(static_cast<int>(reason)) + ")");
  QepSolution sol;
  PetscInt nconv = 0;
  petsc_check(PEPGetConverged(pep, &nconv), "PEPGetConverged");
  PVec xr, xi;
  petsc_check(MatCreateVecs(forms.M, xr.out(), nullptr), "MatCreateVecs");
  petsc_check(VecDuplicate(xr, xi.out()), "VecDuplicate");
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar kr, ki;
    petsc_check(PEPGetEigenpair(pep, i, &kr, &ki, xr, xi), "PEPGetEigenpair");
    Eigenpair ep;
    ep.lambda = kr;
    petsc_check(PEPComputeError(pep, i, PEP_ERROR_BACKWARD, &ep.residual), "PEPComputeError");
    ep.coupling = coupling_.evaluate(ep.lambda, xr);
    if (settings_.keep_eigenvectors) {
      const PetscScalar* x = nullptr;
      PetscInt n = 0;
      petsc_check(VecGetLocalSize(xr, &n), "VecGetLocalSize");
      petsc_check(VecGetArrayRead(xr, &x), "VecGetArrayRead");
      ep.p.assign(x, x + n);
      petsc_check(VecRestoreArrayRead(xr, &x), "VecRestoreArrayRead");
    }
    sol.pairs.push_back(ep);
  }
  std::sort(sol.pairs.begin(), sol.pairs.end(), [](auto& a, auto& b) { return a.lambda < b.lambda; });
  return sol;
}

QepSolution QuadraticEigenSolver::solve_all_dense(int max_dense_dofs) const {
  PetscInt n = 0;
  petsc_check(MatGetSize(forms_.M, &n, nullptr), "MatGetSize");
  if (n > max_dense_dofs)
    throw std::runtime_error("dense eigen-solve refused: " + std::to_string(n) + " dofs > " +
                             std::to_string(max_dense_dofs));
  Mat mats[3] = {coefficients_[0], coefficients_[1], coefficients_[2]};
  PPEP pep;
  petsc_check(PEPCreate(PETSC_COMM_SELF, pep.out()), "PEPCreate");
  petsc_check(PEPSetOperators(pep, 3, mats), "PEPSetOperators");
  petsc_check(PEPSetType(pep, PEPLINEAR), "PEPSetType");
  EPS eps;
  petsc_check(PEPLinearGetEPS(pep, &eps), "PEPLinearGetEPS");
  petsc_check(EPSSetType(eps, EPSLAPACK), "EPSSetType");
  petsc_check(PEPLinearSetExplicitMatrix(pep, PETSC_TRUE), "PEPLinearSetExplicitMatrix");  // LAPACK needs it
  petsc_check(PEPSetDimensions(pep, 2 * n, PETSC_DEFAULT, PETSC_DEFAULT), "PEPSetDimensions");
  petsc_check(PEPSetTolerances(pep, settings_.tolerance, PETSC_DEFAULT), "PEPSetTolerances");
  petsc_check(PEPSolve(pep), "PEPSolve (dense)");
  QepSolution sol = collect(pep);
  if (static_cast<PetscInt>(sol.pairs.size()) != 2 * n)
    throw std::runtime_error("dense eigen-solve returned " + std::to_string(sol.pairs.size()) + " of " +
                             std::to_string(2 * n) + " eigenpairs");
  return sol;
}

}  // namespace rc::modes
