// S(σ) = σ𝓜 − A of the viscous forms, factored by MUMPS in complex arithmetic (complex_lu.hpp) once per σ and then
// solved for any right-hand side (docs/viscous.md, "Response function"). The pattern of S is the same for every σ
// (the union of Â's, M̂'s and the i𝓜 block's), so one solver object refactors numerically and keeps MUMPS's ordering
// and symbolic analysis across σ; a second solve at the same σ costs one forward and backward substitution (0.03 s
// against 0.86 s for the factorisation on the water cylinder's 39 002 unknowns, in the real block form).
#pragma once

#include "complex_lu.hpp"
#include "petsc_handles.hpp"
#include "viscous_forms.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

class ShiftedSolver {
 public:
  // `forms` must outlive the solver.
  explicit ShiftedSolver(const ViscousForms& forms);

  // Factors S(σ) (block form Re σ M̂ + Im σ (i𝓜 block) − Â); nothing when σ is the last factored σ. Throws
  // std::runtime_error naming MUMPS's cause when the factorisation fails (σ on an eigenvalue, a singular matrix,
  // memory).
  void factor(std::complex<double> sigma);

  // x = S(σ)⁻¹ b at the last factored σ (block vectors); with `transposed`, x = S(σ)⁻ᵀ b (the plain transpose: the
  // dual problem of a pencil that is not complex symmetric, viscous_volume_krylov.hpp). Throws std::runtime_error when
  // the solve fails.
  void solve(Vec b, Vec x, bool transposed = false);
  // x[k] = S(σ)⁻¹ b[k] for every k in one pass over the factors (complex_lu.hpp).
  void solve(const std::vector<Vec>& b, const std::vector<Vec>& x);

 private:
  void factor_first(std::complex<double> sigma);
  const ViscousForms& forms_;
  ComplexLu lu_;
  std::vector<std::complex<double>> minus_a_, m_, im_;  // −A, 𝓜 and i𝓜 on the factored pattern, after the first σ
  std::complex<double> sigma_;
  bool factored_ = false;
};

}  // namespace rc::modes
