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

// This rank's share of the pencil: the rows PETSc will give it (block_pencil.cpp splits the complex rows as
// PetscSplitOwnership does). Every rank assembles the whole pencil (a quarter of a second at 183 000 unknowns), but
// the matrices' assembly adds up what the ranks hand in, so each hands in only its own rows.
Triplets owned_rows(const Triplets& all, MPI_Comm comm, int size) {
  PetscInt local = PETSC_DECIDE, global = size;
  petsc_check(PetscSplitOwnership(comm, &local, &global), "PetscSplitOwnership");
  PetscInt end = 0;
  MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, comm);
  const PetscInt begin = end - local;
  Triplets mine;
  for (std::size_t k = 0; k < all.v.size(); ++k)
    if (all.i[k] >= begin && all.i[k] < end) mine.add(all.i[k], all.j[k], all.v[k]);
  return mine;
}

}  // namespace

ViscousForms shell_forms(const ShellPencil& pencil, MPI_Comm comm) {
  ViscousForms forms;
  const int n = pencil.size;
  forms.complex_size = n;
  const Triplets a_real = owned_rows(pencil.a_real, comm, n), a_imag = owned_rows(pencil.a_imag, comm, n),
                 mass = owned_rows(pencil.mass, comm, n);
  forms.A = block_operator(comm, n, a_real, a_imag, mass);
  forms.M = block_mass(comm, n, mass);
  forms.iM = block_imaginary_mass(comm, n, mass);
  forms.coupling = block_vector(forms.A, std::vector<double>(n, 0.0));
  forms.real_slots = block_vector(forms.A, std::vector<double>(n, 1.0));
  return forms;
}

std::vector<ViscousMode> shell_modes_near(const ShellSettings& settings, std::complex<double> target, int pairs,
                                          MPI_Comm comm) {
  const ViscousForms forms = shell_forms(assemble_shell_pencil(settings), comm);
  ViscousSolveSettings solve;
  solve.pairs = pairs;
  // MUMPS's defaults (pivoting threshold 0.01, no refinement) hold the shell's and the sphere's decay to Kore's at
  // the rounding floor once each block's wall rows come first (shell_pencil.cpp); with the wall rows last they lost
  // the mode at high truncations, and the cure then (threshold 0.1, refinement) cost up to five times the time
  // (docs/spherical.md §3).
  std::vector<ViscousMode> modes = backward_errors(forms, viscous_modes_near(forms, target, solve));
  return modes;
}

}  // namespace rc::modes::spherical
