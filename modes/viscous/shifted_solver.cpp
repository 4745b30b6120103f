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
    : forms_(forms), lu_(comm_of(forms.A), "response_", forms.complex_symmetric) {
  // −A on A's pattern, which holds M̂'s and the i𝓜 block's (viscous_forms.cpp).
  petsc_check(MatDuplicate(forms.A, MAT_COPY_VALUES, base_.out()), "MatDuplicate");
  petsc_check(MatScale(base_, -1.0), "MatScale");
  petsc_check(MatDuplicate(base_, MAT_COPY_VALUES, S_.out()), "MatDuplicate");
}

void ShiftedSolver::factor(std::complex<double> sigma) {
  if (factored_ && sigma == sigma_) return;  // factored already
  petsc_check(MatCopy(base_, S_, SAME_NONZERO_PATTERN), "MatCopy");
  petsc_check(MatAXPY(S_, sigma.real(), forms_.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(S_, sigma.imag(), forms_.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
  factored_ = false;
  sigma_ = sigma;
  try {
    lu_.factor(S_);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the factorisation at sigma = " + describe(sigma) + " failed: " + e.what());
  }
  factored_ = true;
}

void ShiftedSolver::solve(Vec b, Vec x, bool transposed) {
  if (!factored_) throw std::logic_error("ShiftedSolver::solve before factor");
  try {
    lu_.solve(b, x, transposed);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the forced solve at sigma = " + describe(sigma_) + " failed: " + e.what());
  }
}

}  // namespace rc::modes
