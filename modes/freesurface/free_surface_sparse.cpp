#include "free_surface_sparse.hpp"

#include "free_surface_quadratic.hpp"
#include "petsc_handles.hpp"
#include "progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rc::modes {

namespace {

constexpr double kTolerance = 1e-12;     // SLEPc's relative residual for each pair
constexpr double kSamePair = 1e-9;       // two targets' pairs closer than this (relative) are one pair
constexpr double kNearlyReal = 1e-4;     // |Im λ| / max(1, |λ|) below this: a split near-double real eigenvalue

PMat to_petsc(const Eigen::SparseMatrix<double>& A) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> R(A);
  std::vector<PetscInt> nnz(R.rows());
  for (Eigen::Index i = 0; i < R.rows(); ++i) nnz[i] = R.outerIndexPtr()[i + 1] - R.outerIndexPtr()[i];
  PMat M;
  petsc_check(MatCreateSeqAIJ(PETSC_COMM_SELF, R.rows(), R.cols(), 0, nnz.data(), M.out()), "MatCreateSeqAIJ");
  std::vector<PetscInt> cols;
  for (Eigen::Index i = 0; i < R.rows(); ++i) {
    const PetscInt row = static_cast<PetscInt>(i), begin = R.outerIndexPtr()[i];
    cols.assign(R.innerIndexPtr() + begin, R.innerIndexPtr() + begin + nnz[i]);
    petsc_check(MatSetValues(M, 1, &row, nnz[i], cols.data(), R.valuePtr() + begin, INSERT_VALUES), "MatSetValues");
  }
  petsc_check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  return M;
}

// TOAR on the quadratic, shift-and-invert at `target` with MUMPS's LU (the quadratic is indefinite there).
void configure(PEP pep, double target, int nev) {
  petsc_check(PEPSetProblemType(pep, PEP_GENERAL), "PEPSetProblemType");
  petsc_check(PEPSetType(pep, PEPTOAR), "PEPSetType");
  petsc_check(PEPSetTarget(pep, target), "PEPSetTarget");
  petsc_check(PEPSetWhichEigenpairs(pep, PEP_TARGET_MAGNITUDE), "PEPSetWhichEigenpairs");
  petsc_check(PEPSetDimensions(pep, nev, 4 * nev, PETSC_DEFAULT), "PEPSetDimensions");
  petsc_check(PEPSetTolerances(pep, kTolerance, PETSC_DEFAULT), "PEPSetTolerances");
  const ST st = pep_shift_invert_mumps(pep, PCLU);
  petsc_check(STSetMatStructure(st, DIFFERENT_NONZERO_PATTERN), "STSetMatStructure");
}

// The converged pairs of one target, each checked real.
std::vector<PartialFillPair> pairs_near(const FreeSurfaceQuadratic& f, Mat mats[3], double target, int nev,
                                        bool keep_pressure, int& skipped, int& short_targets) {
  PPEP pep;
  petsc_check(PEPCreate(PETSC_COMM_SELF, pep.out()), "PEPCreate");
  petsc_check(PEPSetOperators(pep, 3, mats), "PEPSetOperators");
  configure(pep, target, nev);
  petsc_check(PEPSetFromOptions(pep), "PEPSetFromOptions");
  petsc_check(PEPSolve(pep), fmt::format("free surface: the sparse eigensolver failed at {:.6g}", target).c_str());
  PEPConvergedReason reason;
  petsc_check(PEPGetConvergedReason(pep, &reason), "PEPGetConvergedReason");
  PetscInt nconv = 0;
  petsc_check(PEPGetConverged(pep, &nconv), "PEPGetConverged");
  // Shift-and-invert converges the pairs nearest the target first: short of nev (a cluster beyond them, like the
  // accumulation of surface waves at λ → −2, measured 2026-11-27: 4 of 16), the converged ones stand, counted.
  if (nconv < 1)
    throw std::runtime_error(fmt::format("free surface: the sparse eigensolver converged no pair at {:.6g} (SLEPc "
                                         "reason {})", target, static_cast<int>(reason)));
  if (nconv < nev) ++short_targets;
  PVec xr, xi;
  petsc_check(MatCreateVecs(mats[0], xr.out(), nullptr), "MatCreateVecs");
  petsc_check(VecDuplicate(xr, xi.out()), "VecDuplicate");
  std::vector<PartialFillPair> pairs;
  const Eigen::Index n = f.pressure_dofs();
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar kr = 0, ki = 0;
    petsc_check(PEPGetEigenpair(pep, i, &kr, &ki, xr, xi), "PEPGetEigenpair");
    // Real in exact arithmetic; a near-double eigenvalue (the sphere's cluster at λ ≈ −2, |Im λ| 7e-6, measured
    // 2026-11-27) can come back as a complex pair whose vectors span both members: not one pair, so not kept (counted).
    const double scale = std::max(1.0, std::abs(kr));
    if (std::abs(ki) > kNearlyReal * scale)
      throw std::runtime_error(fmt::format("free surface: a complex eigenvalue {} + {}i (target {})", kr, ki, target));
    if (std::abs(ki) > 1e-7 * scale) {
      ++skipped;
      continue;
    }
    const PetscScalar* x = nullptr;
    petsc_check(VecGetArrayRead(xr, &x), "VecGetArrayRead");
    const Eigen::VectorXd p = Eigen::Map<const Eigen::VectorXd>(x, n);
    petsc_check(VecRestoreArrayRead(xr, &x), "VecRestoreArrayRead");
    pairs.push_back(free_surface_pair(f, kr, p));
    if (keep_pressure) pairs.back().pressure.assign(p.data(), p.data() + n);
  }
  return pairs;
}

bool already_found(const std::vector<PartialFillPair>& found, const PartialFillPair& p) {
  return std::any_of(found.begin(), found.end(), [&](const PartialFillPair& q) {
    return std::abs(q.lambda - p.lambda) < kSamePair * std::max(1.0, std::abs(p.lambda));
  });
}

}  // namespace

long free_surface_unknowns(const FESpace& space) {
  return space.ndof() + static_cast<long>(assemble_free_surface_forms(space, 0.0).surface_dofs.size());
}

PartialFillSpectrum solve_partially_filled_near(const FESpace& space, const std::vector<double>& targets,
                                                int per_target, bool keep_pressure) {
  const FreeSurfaceQuadratic f = free_surface_quadratic(space);
  PartialFillSpectrum out = spectrum_integrals(space, f);
  out.complete = false;
  const auto A = f.coefficients();
  std::array<PMat, 3> P{to_petsc(A[0]), to_petsc(A[1]), to_petsc(A[2])};
  Mat mats[3] = {P[0], P[1], P[2]};
  for (const double target : targets) {
    for (auto& p : pairs_near(f, mats, target, per_target, keep_pressure, out.skipped, out.short_targets))
      if (!already_found(out.pairs, p)) out.pairs.push_back(std::move(p));
    progress_tick();
  }
  std::sort(out.pairs.begin(), out.pairs.end(),
            [](const PartialFillPair& x, const PartialFillPair& y) { return x.coupling.E > y.coupling.E; });
  for (const auto& p : out.pairs) out.sum_E += p.coupling.E;
  return out;
}

}  // namespace rc::modes
