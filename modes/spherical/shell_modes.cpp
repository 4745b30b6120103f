#include "shell_modes.hpp"

#include <cmath>

namespace rc::modes::spherical {

Truncation default_truncation(double ekman, double inner_radius, int m, double factor) {
  int n = static_cast<int>(17 * std::pow(ekman, -0.2));
  n = std::max(48, n + n % 2);
  // The full sphere: a quarter above Kore's. Its decay at Kore's own truncation was 8e-11 (Ek = 1e-5) to 6e-4 (1e-7)
  // off the converged value, at 1.25 times it 1e-12 … 4e-12, and the check at 0.8 times is then Kore's truncation.
  // The shell is at the rounding floor already at Kore's (2.5e-13 at 1e-5, 1.1e-12 at 1e-6; docs/spherical.md §3).
  if (inner_radius == 0) n = static_cast<int>(std::lround(1.25 * n));
  n = static_cast<int>(std::lround(n * factor));
  Truncation t;
  t.radial = inner_radius > 0 ? n : (n + 1) / 2;
  t.lmax = n + std::max(m, 1);
  return t;
}

namespace {

// The solver's residual ‖Ax − λ𝓜x‖ / (|λ| ‖x‖) is large beside the derivative rows' large entries (k⁴ at degree k);
// the normwise backward error ‖Ax − λ𝓜x‖ / ((‖A‖ + |λ| ‖𝓜‖) ‖x‖) is what says the solve is sound.
std::vector<ViscousMode> backward_errors(const ViscousForms& forms, std::vector<ViscousMode> modes) {
  PetscReal a = 0, mass = 0;
  petsc_check(MatNorm(forms.A, NORM_INFINITY, &a), "MatNorm");
  petsc_check(MatNorm(forms.M, NORM_INFINITY, &mass), "MatNorm");
  for (ViscousMode& mode : modes) mode.residual *= std::abs(mode.lambda) / (a + std::abs(mode.lambda) * mass);
  return modes;
}

}  // namespace

std::vector<ViscousMode> shell_modes_near(const ShellSettings& settings, std::complex<double> target, int pairs,
                                          MPI_Comm comm) {
  const ShellPencil pencil = assemble_shell_pencil(settings);
  ViscousForms forms;
  const int n = pencil.size;
  forms.complex_size = n;
  forms.A = block_operator(comm, n, pencil.a_real, pencil.a_imag, pencil.mass);
  forms.M = block_mass(comm, n, pencil.mass);
  forms.iM = block_imaginary_mass(comm, n, pencil.mass);
  forms.coupling = block_vector(forms.A, std::vector<double>(n, 0.0));
  forms.real_slots = block_vector(forms.A, std::vector<double>(n, 1.0));
  ViscousSolveSettings solve;
  solve.pairs = pairs;
  // A shell's high harmonics vary as r^l and r^−(l+1) across it, and its factors need more care than MUMPS's
  // defaults (measured, docs/spherical.md §3): with the default pivoting threshold (0.01) they lost the spin-over mode
  // at twice the default truncation (Ek = 1e-4) and 1e-9 of its decay at Ek = 1e-5 (0.1: Kore's values to 2e-13, same
  // time); without iterative refinement the decay at Ek = 1e-6 was 2.8e-10 off (backward error 3.7e-12; one step per
  // solve: 3.5e-13 and 1.3e-17, for half as much time again). The full sphere's basis has no r^−(l+1): at its default
  // truncations it is as accurate without either (1e-12 … 4e-12 at Ek = 1e-5 … 1e-6), where they cost it a quarter
  // to two thirds more time.
  if (settings.inner_radius > 0) {
    solve.factors.pivot_threshold = 0.1;
    solve.factors.refinement_steps = 1;
  }
  std::vector<ViscousMode> modes = backward_errors(forms, viscous_modes_near(forms, target, solve));
  return modes;
}

}  // namespace rc::modes::spherical
