#include "shifted_solver.hpp"

#include <stdexcept>
#include <string>

namespace rc::modes {

namespace {

MPI_Comm comm_of(Mat A) { return PetscObjectComm(reinterpret_cast<PetscObject>(A)); }

std::string describe(std::complex<double> sigma) {
  return std::to_string(sigma.real()) + (sigma.imag() < 0 ? " - " : " + ") + std::to_string(std::abs(sigma.imag())) + "i";
}

}  // namespace

// MUMPS's settings and the -response_ options: complex_lu.hpp.
ShiftedSolver::ShiftedSolver(const ViscousForms& forms)
    : forms_(forms), lu_(comm_of(forms.A), "response_", forms.complex_symmetric) {}

void ShiftedSolver::factor(std::complex<double> sigma) {
  if (factored_ && sigma == sigma_) return;  // factored already
  factored_ = false;
  sigma_ = sigma;
  try {
    if (minus_a_.empty()) {
      factor_first(sigma);
    } else {
      std::vector<std::complex<double>> values(minus_a_.size());
      for (std::size_t k = 0; k < values.size(); ++k) values[k] = minus_a_[k] + sigma.real() * m_[k] + sigma.imag() * im_[k];
      lu_.factor(std::move(values));
    }
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the factorisation at sigma = " + describe(sigma) + " failed: " + e.what());
  }
  factored_ = true;
}

// The first σ is assembled as a sparse matrix (−A on A's pattern, which holds M̂'s and the i𝓜 block's:
// viscous_forms.cpp), which fixes the pattern; −A, 𝓜 and i𝓜 are then read onto it once, and every later σ is their
// combination entry by entry (on a P6 mesh the sparse copy and two MatAXPY took 0.25 s and the reading 0.3–0.5 s of
// each 2.7–3.5 s factorisation; docs/benchmarks.md, "Krylov point").
void ShiftedSolver::factor_first(std::complex<double> sigma) {
  PMat S;
  petsc_check(MatDuplicate(forms_.A, MAT_COPY_VALUES, S.out()), "MatDuplicate");
  petsc_check(MatScale(S, -1.0), "MatScale");
  petsc_check(MatAXPY(S, sigma.real(), forms_.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(S, sigma.imag(), forms_.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
  lu_.factor(S);
  m_ = lu_.entries(forms_.M);
  im_ = lu_.entries(forms_.iM);
  minus_a_ = lu_.entries(forms_.A);
  for (auto& v : minus_a_) v = -v;
}

void ShiftedSolver::solve(Vec b, Vec x, bool transposed) {
  if (!factored_) throw std::logic_error("ShiftedSolver::solve before factor");
  try {
    lu_.solve(b, x, transposed);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the forced solve at sigma = " + describe(sigma_) + " failed: " + e.what());
  }
}

void ShiftedSolver::solve(const std::vector<Vec>& b, const std::vector<Vec>& x) {
  if (!factored_) throw std::logic_error("ShiftedSolver::solve before factor");
  try {
    lu_.solve(b, x);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the forced solve at sigma = " + describe(sigma_) + " failed: " + e.what());
  }
}

}  // namespace rc::modes
