#include "viscous_response.hpp"

#include "mesh_broadcast.hpp"
#include "poincare_forms.hpp"
#include "taylor_hood_space.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::modes {

namespace {

// One KSP (preonly, MUMPS LU) for every σ: S = σ𝓜 − A keeps one nonzero pattern (the union of A's, M̂'s and the i𝓜
// block's), so PETSc refactors numerically and MUMPS keeps its ordering and symbolic analysis across σ.
struct ForcedSolver {
  PMat base, S;  // −A on the union pattern; the current σ𝓜 − A
  PKSP ksp;

  explicit ForcedSolver(const ViscousForms& forms) {
    // The union pattern (MatAXPY skips a zero multiple, hence 1 and then zeroed), then −A on it.
    petsc_check(MatDuplicate(forms.A, MAT_COPY_VALUES, base.out()), "MatDuplicate");
    petsc_check(MatAXPY(base, 1.0, forms.M, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
    petsc_check(MatAXPY(base, 1.0, forms.iM, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
    petsc_check(MatZeroEntries(base), "MatZeroEntries");
    petsc_check(MatAXPY(base, -1.0, forms.A, SUBSET_NONZERO_PATTERN), "MatAXPY");
    petsc_check(MatDuplicate(base, MAT_COPY_VALUES, S.out()), "MatDuplicate");
    MPI_Comm comm;
    petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(S.get()), &comm), "PetscObjectGetComm");
    PC pc;
    Mat F;
    petsc_check(KSPCreate(comm, ksp.out()), "KSPCreate");
    petsc_check(KSPSetOperators(ksp, S, S), "KSPSetOperators");
    petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCLU), "PCSetType");
    petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    petsc_check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
    petsc_check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    petsc_check(MatMumpsSetIcntl(F, 24, 1), "MatMumpsSetIcntl");   // as viscous_eigensolver.cpp
    petsc_check(MatMumpsSetIcntl(F, 14, 100), "MatMumpsSetIcntl");
    petsc_check(KSPSetOptionsPrefix(ksp, "response_"), "KSPSetOptionsPrefix");
    petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
  }

  void solve(const ViscousForms& forms, std::complex<double> sigma, Vec x) {
    // S = σ𝓜 − A in block form: Re σ M̂ + Im σ (i𝓜 block) − Â.
    petsc_check(MatCopy(base, S, SAME_NONZERO_PATTERN), "MatCopy");
    petsc_check(MatAXPY(S, sigma.real(), forms.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
    petsc_check(MatAXPY(S, sigma.imag(), forms.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
    petsc_check(KSPSetOperators(ksp, S, S), "KSPSetOperators");
    const std::string where = "forced solve at sigma = " + std::to_string(sigma.real()) +
                              (sigma.imag() < 0 ? " - " : " + ") + std::to_string(std::abs(sigma.imag())) + "i";
    petsc_check(KSPSolve(ksp, forms.coupling, x), where.c_str());
    KSPConvergedReason reason;
    petsc_check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    if (reason < 0) throw std::runtime_error("the " + where + " failed: " + factor_failure(reason));
  }

  // Why the factorisation failed, in words: MUMPS's INFOG(1) -9/-13/-17/-19/-20 are memory, -10 a singular matrix.
  std::string factor_failure(KSPConvergedReason reason) {
    PC pc;
    Mat F;
    PetscInt infog1 = 0, infog2 = 0;
    petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
    if (PCFactorGetMatrix(pc, &F) == 0 && MatMumpsGetInfog(F, 1, &infog1) == 0 && MatMumpsGetInfog(F, 2, &infog2) == 0 &&
        infog1 < 0) {
      const bool memory = infog1 == -9 || infog1 == -13 || infog1 == -17 || infog1 == -19 || infog1 == -20;
      return "MUMPS INFOG(1) = " + std::to_string(infog1) + ", INFOG(2) = " + std::to_string(infog2) +
             (memory ? " (out of memory: a coarser --mesh-size/--wall-size, or mpirun over more memory)"
                     : infog1 == -10 ? " (singular matrix: sigma on an eigenvalue?)" : "");
    }
    return "KSP reason " + std::to_string(reason);
  }
};

// π fᵀx for the block form x = a + ib: the coupling vector sits on the real slots only.
std::complex<double> moment_of(const ViscousForms& forms, Vec x) {
  MPI_Comm comm;
  petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(x), &comm), "PetscObjectGetComm");
  PetscScalar fa = 0, fb = 0;
  petsc_check(VecDot(x, forms.coupling, &fa), "VecDot");  // Σ f_j a_j
  // Σ f_j b_j: each pair (a_j, b_j) is local to one rank (viscous_forms.cpp).
  const PetscScalar* xs = nullptr;
  const PetscScalar* fs = nullptr;
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(x, &lo, &hi), "VecGetOwnershipRange");
  petsc_check(VecGetArrayRead(x, &xs), "VecGetArrayRead");
  petsc_check(VecGetArrayRead(forms.coupling, &fs), "VecGetArrayRead");
  double local = 0;
  for (PetscInt g = lo; g + 1 < hi; g += 2) local += fs[g - lo] * xs[g + 1 - lo];  // pairs never straddle ranks
  petsc_check(VecRestoreArrayRead(x, &xs), "VecRestoreArrayRead");
  petsc_check(VecRestoreArrayRead(forms.coupling, &fs), "VecRestoreArrayRead");
  MPI_Allreduce(&local, &fb, 1, MPI_DOUBLE, MPI_SUM, comm);
  return std::numbers::pi * std::complex<double>(fa, fb);
}

}  // namespace

std::vector<std::shared_ptr<PVec>> forced_solutions(const ViscousForms& forms,
                                                    const std::vector<std::complex<double>>& sigmas,
                                                    const ResponseProgress& progress) {
  std::vector<std::shared_ptr<PVec>> out;
  ForcedSolver solver(forms);
  for (const auto sigma : sigmas) {
    auto x = std::make_shared<PVec>();
    petsc_check(VecDuplicate(forms.coupling, x->out()), "VecDuplicate");
    solver.solve(forms, sigma, *x);
    out.push_back(std::move(x));
    if (progress) progress(out.size(), sigmas.size());
  }
  return out;
}

struct ForcedResponse::State {
  const ViscousForms& forms;
  ForcedSolver solver;
  PVec x;
  explicit State(const ViscousForms& f) : forms(f), solver(f) {
    petsc_check(VecDuplicate(f.coupling, x.out()), "VecDuplicate");
  }
};

ForcedResponse::ForcedResponse(const ViscousForms& forms) : state_(std::make_unique<State>(forms)) {}
ForcedResponse::~ForcedResponse() = default;

std::complex<double> ForcedResponse::operator()(std::complex<double> sigma) {
  state_->solver.solve(state_->forms, sigma, state_->x);
  return moment_of(state_->forms, state_->x);
}

std::vector<std::complex<double>> viscous_response(const ViscousForms& forms,
                                                   const std::vector<std::complex<double>>& sigmas,
                                                   const ResponseProgress& progress) {
  std::vector<std::complex<double>> out;
  ForcedResponse response(forms);
  for (const auto sigma : sigmas) {
    out.push_back(response(sigma));
    if (progress) progress(out.size(), sigmas.size());
  }
  return out;
}

ViscousForms assemble_cavity_forms(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, double ekman,
                                   MPI_Comm comm) {
  const TaylorHoodSpace space(mesh_on_root([&] { return geometry::mesh_meridian(shape, mesh); }, PETSC_COMM_WORLD));
  const double centroid_z = integrate_fluid(space.geometry()).centroid_z;
  return assemble_viscous_forms(space, centroid_z, ekman, comm);
}

std::vector<std::complex<double>> cavity_response(const geometry::ShapeSpec& shape, geometry::MeshOptions mesh,
                                                  double ekman, const std::vector<std::complex<double>>& sigmas,
                                                  long* unknowns, const ResponseProgress& progress) {
  const ViscousForms forms = assemble_cavity_forms(shape, mesh, ekman);
  if (unknowns) *unknowns = 2L * forms.complex_size;
  return viscous_response(forms, sigmas, progress);
}

}  // namespace rc::modes
