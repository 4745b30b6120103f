#include "viscous_eigensolver.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::modes {
namespace {

using PEPS = PetscHandle<EPS, EPSDestroy>;

double dot(Vec a, Vec b) {
  PetscScalar s = 0;
  petsc_check(VecDot(a, b, &s), "VecDot");
  return s;
}

// x = a + i b on the real slots (the complex problem's unknowns); the imaginary slots hold −i x.
std::complex<double> coupling_residue(const ViscousForms& forms, Vec xr, Vec xi) {
  PVec a, b, Ma, Mb;
  for (PVec* v : {&a, &b, &Ma, &Mb}) petsc_check(VecDuplicate(xr, v->out()), "VecDuplicate");
  petsc_check(VecPointwiseMult(a, xr, forms.real_slots), "VecPointwiseMult");
  petsc_check(VecPointwiseMult(b, xi, forms.real_slots), "VecPointwiseMult");
  petsc_check(MatMult(forms.M, a, Ma), "MatMult");
  petsc_check(MatMult(forms.M, b, Mb), "MatMult");
  const std::complex<double> fx(dot(forms.coupling, a), dot(forms.coupling, b));
  const std::complex<double> xMx(dot(a, Ma) - dot(b, Mb), 2 * dot(a, Mb));
  if (std::abs(xMx) == 0) throw std::runtime_error("viscous mode with zero kinetic-energy form");
  return std::numbers::pi * fx * fx / xMx;
}

}  // namespace

std::vector<ViscousMode> viscous_modes_near(const ViscousForms& forms, double target,
                                            const ViscousSolveSettings& settings) {
  MPI_Comm comm = PETSC_COMM_WORLD;
  petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(forms.A.get()), &comm), "PetscObjectGetComm");
  PEPS eps;
  petsc_check(EPSCreate(comm, eps.out()), "EPSCreate");
  // Own prefix (-viscous_eps_..., -viscous_st_...) and two MUMPS defaults the saddle-point pencil needs:
  //  * null-pivot detection (ICNTL 24), because a Taylor–Hood triangle with no interior vertex (where the wall
  //    meets the axis) carries a spurious pressure mode that parallel MUMPS may otherwise report as a singular
  //    matrix; that mode has no mass and never touches the eigenvalues sought;
  //  * 100 % more workspace than the analysis estimates (ICNTL 14), because the zero pressure block makes
  //    MUMPS delay many pivots (measured: 24 000 of 200 000), which overruns the default 20 %.
  petsc_check(EPSSetOptionsPrefix(eps, "viscous_"), "EPSSetOptionsPrefix");
  for (auto [name, value] : {std::pair{"-viscous_st_mat_mumps_icntl_24", "1"}, {"-viscous_st_mat_mumps_icntl_14", "100"}}) {
    PetscBool given = PETSC_FALSE;
    petsc_check(PetscOptionsHasName(nullptr, nullptr, name, &given), "PetscOptionsHasName");
    if (!given) petsc_check(PetscOptionsSetValue(nullptr, name, value), "PetscOptionsSetValue");
  }
  petsc_check(EPSSetOperators(eps, forms.A, forms.M), "EPSSetOperators");
  petsc_check(EPSSetProblemType(eps, EPS_GNHEP), "EPSSetProblemType");
  petsc_check(EPSSetType(eps, EPSKRYLOVSCHUR), "EPSSetType");
  petsc_check(EPSSetTarget(eps, target), "EPSSetTarget");
  petsc_check(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
  petsc_check(EPSSetDimensions(eps, 2 * settings.pairs, PETSC_DEFAULT, PETSC_DEFAULT), "EPSSetDimensions");
  petsc_check(EPSSetTolerances(eps, settings.tolerance, settings.max_iterations), "EPSSetTolerances");
  ST st;
  KSP ksp;
  PC pc;
  petsc_check(EPSGetST(eps, &st), "EPSGetST");
  petsc_check(STSetType(st, STSINVERT), "STSetType");
  petsc_check(STGetKSP(st, &ksp), "STGetKSP");
  petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCLU), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  petsc_check(EPSSetFromOptions(eps), "EPSSetFromOptions");
  petsc_check(EPSSolve(eps), "EPSSolve (shift-and-invert of the viscous pencil; a singular factorisation means "
                             "the target sits on an eigenvalue or the mesh is degenerate)");
  EPSConvergedReason reason;
  petsc_check(EPSGetConvergedReason(eps, &reason), "EPSGetConvergedReason");
  PetscInt converged = 0;
  petsc_check(EPSGetConverged(eps, &converged), "EPSGetConverged");
  if (reason < 0 && converged == 0)
    throw std::runtime_error("SLEPc did not converge near lambda = " + std::to_string(target) +
                             " (reason " + std::to_string(reason) + ")");

  PVec xr, xi;
  petsc_check(MatCreateVecs(forms.A, xr.out(), nullptr), "MatCreateVecs");
  petsc_check(VecDuplicate(xr, xi.out()), "VecDuplicate");
  std::vector<ViscousMode> modes;
  for (PetscInt k = 0; k < converged; ++k) {
    PetscScalar kr = 0, ki = 0;
    petsc_check(EPSGetEigenpair(eps, k, &kr, &ki, xr, xi), "EPSGetEigenpair");
    if (!(ki > 0)) continue;  // the conjugate problem's copy (or a real eigenvalue: none is physical with Ek > 0)
    ViscousMode m;
    m.lambda = {kr, ki};
    petsc_check(EPSComputeError(eps, k, EPS_ERROR_RELATIVE, &m.residual), "EPSComputeError");
    m.residue = coupling_residue(forms, xr, xi);
    modes.push_back(m);
  }
  if (modes.empty())
    throw std::runtime_error("SLEPc found no damped mode near lambda = " + std::to_string(target) + " (" +
                             std::to_string(converged) + " eigenpairs converged)");
  std::sort(modes.begin(), modes.end(), [&](const ViscousMode& a, const ViscousMode& b) {
    return std::abs(a.lambda - target) < std::abs(b.lambda - target);
  });
  return modes;
}

}  // namespace rc::modes
