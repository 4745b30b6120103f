#include "viscous_eigensolver.hpp"

#include "complex_lu.hpp"
#include "progress.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rc::modes {
namespace {

// Each Krylov-Schur restart lets the run's progress line come (progress.hpp).
PetscErrorCode tick_monitor(EPS, PetscInt, PetscInt, PetscScalar*, PetscScalar*, PetscReal*, PetscInt, void*) {
  progress_tick();
  return 0;
}


using PEPS = PetscHandle<EPS, EPSDestroy>;

double dot(Vec a, Vec b) {
  PetscScalar s = 0;
  petsc_check(VecDot(a, b, &s), "VecDot");
  return s;
}

double norm(Vec a) {
  PetscReal s = 0;
  petsc_check(VecNorm(a, NORM_2, &s), "VecNorm");
  return s;
}

// The shift-and-invert operator T v = S⁻¹ M̂ v, S the block of A − τ𝓜, factorised in complex arithmetic
// (complex_lu.hpp). In the real block form, the symmetric form of S (its imaginary rows negated) factorised as LDLᵀ
// was measured 4× slower than the LU (15 s against 3.5 s on the Ek = 1e-4 sphere): the indefinite saddle point makes
// MUMPS's 2 × 2 pivoting expensive.
struct ShiftInvert {
  const ViscousForms* forms = nullptr;
  std::unique_ptr<ComplexLu> lu;
  PVec work;
};

PetscErrorCode apply_shift_invert(Mat T, Vec x, Vec y) {
  ShiftInvert* op = nullptr;
  PetscCall(MatShellGetContext(T, &op));
  PetscCall(MatMult(op->forms->M, x, op->work));
  try {
    op->lu->solve(op->work, y);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  return 0;
}

// S = Â − Re τ M̂ − Im τ (block of i𝓜), factorised once (MUMPS's settings and the -viscous_st_ options: complex_lu.hpp).
void factorise(ShiftInvert& op, std::complex<double> target, MPI_Comm comm) {
  PMat S;
  petsc_check(MatDuplicate(op.forms->A, MAT_COPY_VALUES, S.out()), "MatDuplicate");
  petsc_check(MatAXPY(S, -target.real(), op.forms->M, SUBSET_NONZERO_PATTERN), "MatAXPY");  // Â holds their patterns
  petsc_check(MatAXPY(S, -target.imag(), op.forms->iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
  op.lu = std::make_unique<ComplexLu>(comm, "viscous_st_");
  op.lu->factor(S);
  petsc_check(MatCreateVecs(op.forms->M, op.work.out(), nullptr), "MatCreateVecs");
}

// x = a + ib on the real slots (the complex problem's unknowns): fᵀx and xᵀ𝓜x (unconjugated); E_c = π (fᵀx)² / xᵀ𝓜x.
struct CouplingForms {
  std::complex<double> fx, xMx;
  std::complex<double> gx;  // the offset functional's gᵀx (a free surface's only)
  double xbarMx = 0;  // x̄ᵀ𝓜x = ∫∫ |V|² r dr dz
  std::complex<double> residue() const { return std::numbers::pi * fx * fx / xMx; }
};

CouplingForms coupling_forms(const ViscousForms& forms, Vec xr, Vec xi) {
  PVec a, b, Ma, Mb;
  for (PVec* v : {&a, &b, &Ma, &Mb}) petsc_check(VecDuplicate(xr, v->out()), "VecDuplicate");
  petsc_check(VecPointwiseMult(a, xr, forms.real_slots), "VecPointwiseMult");
  petsc_check(VecPointwiseMult(b, xi, forms.real_slots), "VecPointwiseMult");
  petsc_check(MatMult(forms.M, a, Ma), "MatMult");
  petsc_check(MatMult(forms.M, b, Mb), "MatMult");
  CouplingForms c;
  c.fx = {dot(forms.coupling, a), dot(forms.coupling, b)};
  if (forms.offset_coupling.get() != nullptr) c.gx = {dot(forms.offset_coupling, a), dot(forms.offset_coupling, b)};
  c.xMx = {dot(a, Ma) - dot(b, Mb), 2 * dot(a, Mb)};
  c.xbarMx = dot(a, Ma) + dot(b, Mb);
  if (std::abs(c.xMx) == 0) throw std::runtime_error("viscous mode with zero kinetic-energy form");
  return c;
}

// The scale normalised_vector applies: xᵀ𝓜x = 1 and Re a ≥ 0, a = √(π/2) fᵀx.
std::complex<double> table_scale(const CouplingForms& c) {
  std::complex<double> scale = 1.0 / std::sqrt(c.xMx);
  if ((std::sqrt(std::numbers::pi / 2) * c.fx * scale).real() < 0) scale = -scale;
  return scale;
}

// The complex eigenvector x_j = Xr[2j] + i Xi[2j] on rank 0 (empty elsewhere), scaled as the table normalises
// its mode: xᵀ𝓜x = 1, and the sign that makes a = √(π/2) fᵀx the table's a = sqrt(E_c / 2) (Re a ≥ 0).
std::vector<std::complex<double>> normalised_vector(Vec xr, Vec xi, const CouplingForms& c, double& conjugate_norm) {
  const std::complex<double> scale = table_scale(c);
  conjugate_norm = c.xbarMx * std::norm(scale);
  std::vector<std::complex<double>> x;
  for (Vec v : {xr, xi}) {
    VecScatter gather;
    Vec all;
    petsc_check(VecScatterCreateToZero(v, &gather, &all), "VecScatterCreateToZero");
    petsc_check(VecScatterBegin(gather, v, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    petsc_check(VecScatterEnd(gather, v, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    PetscInt n = 0;
    petsc_check(VecGetLocalSize(all, &n), "VecGetLocalSize");
    const PetscScalar* data = nullptr;
    petsc_check(VecGetArrayRead(all, &data), "VecGetArrayRead");
    if (x.empty()) x.assign(static_cast<std::size_t>(n / 2), 0.0);
    for (PetscInt j = 0; 2 * j < n; ++j)
      x[j] += (v == xr ? std::complex<double>(data[2 * j], 0) : std::complex<double>(0, data[2 * j])) * scale;
    petsc_check(VecRestoreArrayRead(all, &data), "VecRestoreArrayRead");
    VecDestroy(&all);
    VecScatterDestroy(&gather);
  }
  return x;  // size 0 on the ranks other than 0 (their gathered vector is empty)
}

// The normalised mode (normalised_vector's scaling) in block form: slot 2j holds Re(s x_j), 2j + 1 Im(s x_j), with
// x_j = Xr[2j] + i Xi[2j] (the even slots carry the complex problem's unknowns) and s = scale.
std::shared_ptr<PVec> block_of(Vec xr, Vec xi, std::complex<double> scale) {
  auto out = std::make_shared<PVec>();
  petsc_check(VecDuplicate(xr, out->out()), "VecDuplicate");
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(xr, &lo, &hi), "VecGetOwnershipRange");
  const PetscScalar *re = nullptr, *im = nullptr;
  PetscScalar* b = nullptr;
  petsc_check(VecGetArrayRead(xr, &re), "VecGetArrayRead");
  petsc_check(VecGetArrayRead(xi, &im), "VecGetArrayRead");
  petsc_check(VecGetArray(*out, &b), "VecGetArray");
  for (PetscInt g = lo; g + 1 < hi; g += 2) {  // pairs never straddle ranks (viscous_forms.cpp)
    const std::complex<double> x = scale * std::complex<double>(re[g - lo], im[g - lo]);
    b[g - lo] = x.real();
    b[g + 1 - lo] = x.imag();
  }
  petsc_check(VecRestoreArray(*out, &b), "VecRestoreArray");
  petsc_check(VecRestoreArrayRead(xi, &im), "VecRestoreArrayRead");
  petsc_check(VecRestoreArrayRead(xr, &re), "VecRestoreArrayRead");
  return out;
}

// The block eigenvector X = P + iQ of (Â, M̂) for λ: ‖ÂX − λM̂X‖ / (|λ| ‖X‖) in real arithmetic.
double block_residual(const ViscousForms& forms, Vec P, Vec Q, std::complex<double> lambda) {
  PVec AP, AQ, MP, MQ;
  for (PVec* v : {&AP, &AQ, &MP, &MQ}) petsc_check(VecDuplicate(P, v->out()), "VecDuplicate");
  petsc_check(MatMult(forms.A, P, AP), "MatMult");
  petsc_check(MatMult(forms.A, Q, AQ), "MatMult");
  petsc_check(MatMult(forms.M, P, MP), "MatMult");
  petsc_check(MatMult(forms.M, Q, MQ), "MatMult");
  // Re: ÂP − λr M̂P + λi M̂Q;  Im: ÂQ − λr M̂Q − λi M̂P.
  petsc_check(VecAXPBYPCZ(AP, -lambda.real(), lambda.imag(), 1.0, MP, MQ), "VecAXPBYPCZ");
  petsc_check(VecAXPBYPCZ(AQ, -lambda.real(), -lambda.imag(), 1.0, MQ, MP), "VecAXPBYPCZ");
  const double r = std::hypot(norm(AP), norm(AQ)), x = std::hypot(norm(P), norm(Q));
  return r / (std::abs(lambda) * x);
}

// Which problem an eigenvector of T belongs to: the wanted one has the pairs (x, −ix), i.e. odd = −i·even.
bool is_wanted_pair_structure(Vec Xr, Vec Xi) {
  const PetscScalar *re = nullptr, *im = nullptr;
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(Xr, &lo, &hi), "VecGetOwnershipRange");
  petsc_check(VecGetArrayRead(Xr, &re), "VecGetArrayRead");
  petsc_check(VecGetArrayRead(Xi, &im), "VecGetArrayRead");
  double local[2] = {0, 0};  // ‖odd + i even‖², ‖odd − i even‖²
  for (PetscInt g = lo; g + 1 < hi; g += 2) {  // pairs never straddle ranks (viscous_forms.cpp)
    const std::complex<double> even(re[g - lo], im[g - lo]), odd(re[g + 1 - lo], im[g + 1 - lo]);
    local[0] += std::norm(odd + std::complex<double>(0, 1) * even);
    local[1] += std::norm(odd - std::complex<double>(0, 1) * even);
  }
  petsc_check(VecRestoreArrayRead(Xr, &re), "VecRestoreArrayRead");
  petsc_check(VecRestoreArrayRead(Xi, &im), "VecRestoreArrayRead");
  double global[2] = {0, 0};
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm(reinterpret_cast<PetscObject>(Xr)));
  return global[0] < global[1];
}

}  // namespace

namespace {

// SLEPc's Krylov-Schur on the shell operator T = (A − target 𝓜)⁻¹𝓜, asked for `pairs` wanted θ and their conjugates.
void solve_shift_invert(EPS eps, Mat T, const ViscousSolveSettings& settings) {
  petsc_check(EPSSetOptionsPrefix(eps, "viscous_"), "EPSSetOptionsPrefix");
  petsc_check(EPSSetOperators(eps, T, nullptr), "EPSSetOperators");
  petsc_check(EPSSetProblemType(eps, EPS_NHEP), "EPSSetProblemType");
  petsc_check(EPSSetType(eps, EPSKRYLOVSCHUR), "EPSSetType");
  petsc_check(EPSSetWhichEigenpairs(eps, EPS_LARGEST_MAGNITUDE), "EPSSetWhichEigenpairs");
  // Each wanted θ comes with its conjugate: ask for both.
  petsc_check(EPSSetDimensions(eps, 2 * settings.pairs, PETSC_DEFAULT, PETSC_DEFAULT), "EPSSetDimensions");
  petsc_check(EPSSetTolerances(eps, settings.tolerance, settings.max_iterations), "EPSSetTolerances");
  petsc_check(EPSSetFromOptions(eps), "EPSSetFromOptions");
  petsc_check(EPSMonitorSet(eps, tick_monitor, nullptr, nullptr), "EPSMonitorSet");
  petsc_check(EPSSolve(eps), "EPSSolve (shift-and-invert of the viscous pencil)");
}

// The converged pairs of the wanted problem as damped modes (λ = target + 1/θ with Im λ > 0), with their residues.
std::vector<ViscousMode> damped_modes(EPS eps, PetscInt converged, const ViscousForms& forms,
                                      std::complex<double> target, const ViscousSolveSettings& settings) {
  PVec Xr, Xi, minusXi;
  petsc_check(MatCreateVecs(forms.A, Xr.out(), nullptr), "MatCreateVecs");
  petsc_check(VecDuplicate(Xr, Xi.out()), "VecDuplicate");
  petsc_check(VecDuplicate(Xr, minusXi.out()), "VecDuplicate");
  std::vector<ViscousMode> modes;
  for (PetscInt k = 0; k < converged; ++k) {
    PetscScalar tr = 0, ti = 0;
    petsc_check(EPSGetEigenpair(eps, k, &tr, &ti, Xr, Xi), "EPSGetEigenpair");
    if (!(ti > 0)) continue;  // one of each conjugate pair; the other is its mirror image
    std::complex<double> theta(tr, ti);
    Vec imag_part = Xi;
    if (!is_wanted_pair_structure(Xr, Xi)) {  // the conjugate problem's; the wanted one is the conjugate pair
      theta = std::conj(theta);
      petsc_check(VecAXPBY(minusXi, -1.0, 0.0, Xi), "VecAXPBY");
      imag_part = minusXi;
    }
    ViscousMode m;
    m.lambda = target + 1.0 / theta;
    if (!(m.lambda.imag() > 0)) continue;  // not a damped mode of the wanted problem (none exists with Ek > 0)
    const CouplingForms c = coupling_forms(forms, Xr, imag_part);
    m.residue = c.residue();
    if (forms.offset_coupling.get() != nullptr) m.offset = std::sqrt(std::numbers::pi / 2) * c.gx * table_scale(c);
    if (settings.keep_vector) m.vector = normalised_vector(Xr, imag_part, c, m.conjugate_norm);
    if (settings.keep_block) m.block = block_of(Xr, imag_part, table_scale(c));
    m.residual = block_residual(forms, Xr, imag_part, m.lambda);
    modes.push_back(m);
  }
  return modes;
}

// Block-form helpers for the left eigenvectors: v ← s v for a complex s, and v ← v̄ (the odd slots negated).
void scale_block(Vec v, std::complex<double> s) {
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(v, &lo, &hi), "VecGetOwnershipRange");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  for (PetscInt g = 0; g + 1 < hi - lo; g += 2) {  // pairs never straddle ranks (block_pencil.hpp)
    const std::complex<double> x = s * std::complex<double>(a[g], a[g + 1]);
    a[g] = x.real();
    a[g + 1] = x.imag();
  }
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
}

void conjugate_block(Vec v) {
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(v, &lo, &hi), "VecGetOwnershipRange");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  for (PetscInt g = 1; g < hi - lo; g += 2) a[g] = -a[g];
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
}

// ‖Aᵀy − λ𝓜y‖ / (|λ| ‖y‖). The block of the complex Aᵀ is not Âᵀ (that is the block of Aᴴ): Aᵀy = conj(Âᵀ ȳ).
double left_residual(const ViscousForms& forms, Vec y, std::complex<double> lambda) {
  PVec c, r, m;
  for (PVec* v : {&c, &r, &m}) petsc_check(VecDuplicate(y, v->out()), "VecDuplicate");
  petsc_check(VecCopy(y, c), "VecCopy");
  conjugate_block(c);
  petsc_check(MatMultTranspose(forms.A, c, r), "MatMultTranspose");
  conjugate_block(r);
  petsc_check(MatMult(forms.M, y, m), "MatMult");  // 𝓜 real symmetric: the block of 𝓜ᵀ y is M̂ y
  petsc_check(VecAXPY(r, -lambda.real(), m), "VecAXPY");
  petsc_check(MatMult(forms.iM, y, m), "MatMult");
  petsc_check(VecAXPY(r, -lambda.imag(), m), "VecAXPY");
  return norm(r) / (std::abs(lambda) * norm(y));
}

// Inverse iteration y ← S⁻ᵀ𝓜y with op's factors, at most `steps` solves or until the residual is below `wanted` or
// stalls; returns the residual.
double left_iteration(const ShiftInvert& op, const ViscousMode& mode, Vec y, int steps, double wanted) {
  PVec w;
  petsc_check(VecDuplicate(y, w.out()), "VecDuplicate");
  double residual = left_residual(*op.forms, y, mode.lambda);
  for (int k = 0; k < steps && residual > wanted; ++k) {
    petsc_check(MatMult(op.forms->M, y, w), "MatMult");
    op.lu->solve(w, y, true);
    scale_block(y, 1.0 / norm(y));
    const double next = left_residual(*op.forms, y, mode.lambda);
    if (k > 0 && next > 0.5 * residual) return next;  // stalled at the eigenvalue's own accuracy
    residual = next;
  }
  return residual;
}

// The left eigenvector of mode (x = mode.block): inverse iteration with the transposed factors, from x̄ — the left
// vector of the ideal limit, where A is Hermitian. With the search's factors (S = A − τ𝓜) it converges at the rate
// |λ − τ| / |λ' − τ| of the next mode λ', slow for a far target; when three solves do not do, S is factorised again
// at λ itself (just off it, 1e-6 |λ|), where one or two solves do. Normalised to yᵀ𝓜x = 1. Throws when it does not
// converge.
void add_left_vector(const ShiftInvert& op, ViscousMode& mode) {
  const ViscousForms& forms = *op.forms;
  const Vec x = *mode.block;
  auto y = std::make_shared<PVec>();
  petsc_check(VecDuplicate(x, y->out()), "VecDuplicate");
  petsc_check(VecCopy(x, *y), "VecCopy");
  conjugate_block(*y);
  const double wanted = std::max(10 * mode.residual, 1e-13);
  double residual = left_iteration(op, mode, *y, 3, wanted);
  if (residual > wanted) {
    ShiftInvert near;
    near.forms = &forms;
    factorise(near, mode.lambda + 1e-6 * std::abs(mode.lambda), PetscObjectComm(reinterpret_cast<PetscObject>(x)));
    residual = left_iteration(near, mode, *y, 10, wanted);
  }
  if (!(residual < 1e-8))
    throw std::runtime_error("the left eigenvector of the damped mode at " + std::to_string(mode.lambda.real()) +
                             " + " + std::to_string(mode.lambda.imag()) + "i did not converge (residual " +
                             std::to_string(residual) + ")");
  PVec w;
  petsc_check(VecDuplicate(x, w.out()), "VecDuplicate");
  petsc_check(MatMult(forms.M, x, w), "MatMult");
  const std::complex<double> yMx = block_bilinear(*y, w);
  if (std::abs(yMx) == 0) throw std::runtime_error("a damped mode orthogonal to its left eigenvector (a defective pencil)");
  scale_block(*y, 1.0 / yMx);
  mode.left = y;
  mode.left_residual = residual;
}

}  // namespace

std::vector<ViscousMode> viscous_modes_near(const ViscousForms& forms, std::complex<double> target,
                                            const ViscousSolveSettings& settings) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(forms.A.get()));
  ShiftInvert op;
  op.forms = &forms;
  factorise(op, target, comm);
  PetscInt local = 0, global = 0;
  petsc_check(MatGetLocalSize(forms.A, &local, nullptr), "MatGetLocalSize");
  petsc_check(MatGetSize(forms.A, &global, nullptr), "MatGetSize");
  PMat T;
  petsc_check(MatCreateShell(comm, local, local, global, global, &op, T.out()), "MatCreateShell");
  petsc_check(MatShellSetOperation(T, MATOP_MULT, reinterpret_cast<void (*)(void)>(apply_shift_invert)),
              "MatShellSetOperation");
  PEPS eps;
  petsc_check(EPSCreate(comm, eps.out()), "EPSCreate");
  solve_shift_invert(eps, T, settings);
  EPSConvergedReason reason;
  petsc_check(EPSGetConvergedReason(eps, &reason), "EPSGetConvergedReason");
  PetscInt converged = 0;
  petsc_check(EPSGetConverged(eps, &converged), "EPSGetConverged");
  const std::string near = "near lambda = " + std::to_string(target.real()) + " + " + std::to_string(target.imag()) + "i";
  if (reason < 0 && converged == 0)
    throw std::runtime_error("SLEPc did not converge " + near + " (reason " + std::to_string(reason) + ")");
  ViscousSolveSettings wanted = settings;
  wanted.keep_block = settings.keep_block || settings.left_vectors;
  std::vector<ViscousMode> modes = damped_modes(eps, converged, forms, target, wanted);
  if (settings.left_vectors)
    for (ViscousMode& m : modes) add_left_vector(op, m);
  if (modes.empty())
    throw std::runtime_error("SLEPc found no damped mode " + near + " (" + std::to_string(converged) +
                             " eigenpairs converged)");
  std::sort(modes.begin(), modes.end(), [&](const ViscousMode& a, const ViscousMode& b) {
    return std::abs(a.lambda - target) < std::abs(b.lambda - target);
  });
  return modes;
}

}  // namespace rc::modes
