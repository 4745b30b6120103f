#include "stiffness_solver.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace rc::modes {

StiffnessSolver::StiffnessSolver(Mat M, const char* prefix, std::string name) : name_(std::move(name)) {
  petsc_check(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(M)), ksp_.out()), "KSPCreate");
  petsc_check(KSPSetOptionsPrefix(ksp_, prefix), "KSPSetOptionsPrefix");
  petsc_check(KSPSetOperators(ksp_, M, M), "KSPSetOperators");
  petsc_check(KSPSetType(ksp_, KSPPREONLY), "KSPSetType");
  PC pc;
  petsc_check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCCHOLESKY), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  petsc_check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  petsc_check(KSPSetUp(ksp_), ("factorising " + name_).c_str());
  petsc_check(MatCreateVecs(M, x_.out(), b_.out()), "MatCreateVecs");
  petsc_check(VecScatterCreateToAll(x_, to_all_.out(), x_all_.out()), "VecScatterCreateToAll");
}

void StiffnessSolver::solve(Vec b, Vec x) const {
  petsc_check(KSPSolve(ksp_, b, x), ("solving with " + name_).c_str());
  KSPConvergedReason reason;
  petsc_check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  if (reason < 0)
    throw std::runtime_error("the factorisation of " + name_ + " failed (KSP reason " +
                             std::to_string(static_cast<int>(reason)) + ")");
}

void StiffnessSolver::solve(const std::vector<double>& b, std::vector<double>& x) const {
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(b_, &lo, &hi), "VecGetOwnershipRange");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(b_, &a), "VecGetArray");
  std::copy(b.begin() + lo, b.begin() + hi, a);
  petsc_check(VecRestoreArray(b_, &a), "VecRestoreArray");
  solve(b_.get(), x_.get());
  petsc_check(VecScatterBegin(to_all_, x_, x_all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  petsc_check(VecScatterEnd(to_all_, x_, x_all_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* c = nullptr;
  petsc_check(VecGetArrayRead(x_all_, &c), "VecGetArrayRead");
  x.assign(c, c + b.size());
  petsc_check(VecRestoreArrayRead(x_all_, &c), "VecRestoreArrayRead");
}

}  // namespace rc::modes
