#include "shifted_solver.hpp"

#include <stdexcept>
#include <string>

namespace rc::modes {

ShiftedSolver::ShiftedSolver(const ViscousForms& forms) : forms_(forms) {
  // The union pattern (MatAXPY skips a zero multiple, hence 1 and then zeroed), then −A on it.
  petsc_check(MatDuplicate(forms.A, MAT_COPY_VALUES, base_.out()), "MatDuplicate");
  petsc_check(MatAXPY(base_, 1.0, forms.M, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(base_, 1.0, forms.iM, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatZeroEntries(base_), "MatZeroEntries");
  petsc_check(MatAXPY(base_, -1.0, forms.A, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatDuplicate(base_, MAT_COPY_VALUES, S_.out()), "MatDuplicate");
  MPI_Comm comm;
  petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(S_.get()), &comm), "PetscObjectGetComm");
  PC pc;
  Mat F;
  petsc_check(KSPCreate(comm, ksp_.out()), "KSPCreate");
  petsc_check(KSPSetOperators(ksp_, S_, S_), "KSPSetOperators");
  petsc_check(KSPSetType(ksp_, KSPPREONLY), "KSPSetType");
  petsc_check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCLU), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  petsc_check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
  petsc_check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
  petsc_check(MatMumpsSetIcntl(F, 24, 1), "MatMumpsSetIcntl");   // as viscous_eigensolver.cpp
  petsc_check(MatMumpsSetIcntl(F, 14, 100), "MatMumpsSetIcntl");
  petsc_check(KSPSetOptionsPrefix(ksp_, "response_"), "KSPSetOptionsPrefix");
  petsc_check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
}

void ShiftedSolver::factor(std::complex<double> sigma) {
  if (factored_ && sigma == sigma_) return;  // factored already
  petsc_check(MatCopy(base_, S_, SAME_NONZERO_PATTERN), "MatCopy");
  petsc_check(MatAXPY(S_, sigma.real(), forms_.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(S_, sigma.imag(), forms_.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(KSPSetOperators(ksp_, S_, S_), "KSPSetOperators");
  sigma_ = sigma;
  factored_ = true;
  // PETSc factors lazily, at the next solve; a failure there is named by solve().
}

void ShiftedSolver::solve(Vec b, Vec x) {
  if (!factored_) throw std::logic_error("ShiftedSolver::solve before factor");
  const std::string where = "forced solve at sigma = " + std::to_string(sigma_.real()) +
                            (sigma_.imag() < 0 ? " - " : " + ") + std::to_string(std::abs(sigma_.imag())) + "i";
  petsc_check(KSPSolve(ksp_, b, x), where.c_str());
  KSPConvergedReason reason;
  petsc_check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  if (reason < 0) throw std::runtime_error("the " + where + " failed: " + failure(reason));
}

// Why the factorisation failed, in words: MUMPS's INFOG(1) -9/-13/-17/-19/-20 are memory, -10 a singular matrix.
std::string ShiftedSolver::failure(KSPConvergedReason reason) {
  PC pc;
  Mat F;
  PetscInt infog1 = 0, infog2 = 0;
  petsc_check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  if (PCFactorGetMatrix(pc, &F) == 0 && MatMumpsGetInfog(F, 1, &infog1) == 0 && MatMumpsGetInfog(F, 2, &infog2) == 0 &&
      infog1 < 0) {
    const bool memory = infog1 == -9 || infog1 == -13 || infog1 == -17 || infog1 == -19 || infog1 == -20;
    return "MUMPS INFOG(1) = " + std::to_string(infog1) + ", INFOG(2) = " + std::to_string(infog2) +
           (memory ? " (out of memory: a coarser --mesh-size/--wall-size, or mpirun over more memory)"
                   : infog1 == -10 ? " (singular matrix: sigma on an eigenvalue?)" : "");
  }
  return "KSP reason " + std::to_string(reason);
}

}  // namespace rc::modes
