// Damped modes of the fluid in a sphere or a spherical shell near a target, from the spectral pencil of
// shell_pencil.hpp, by the viscous solver's shift-and-invert (viscous/viscous_eigensolver.hpp: SLEPc's
// Krylov–Schur, the complex LU of MUMPS).
#pragma once

#include "shell_pencil.hpp"
#include "viscous_eigensolver.hpp"

#include <mpi.h>

#include <complex>
#include <vector>

namespace rc::modes::spherical {

// The truncation Kore's tests use (its Ncheb: 17 Ek^−1/5, at least 48, even) — 1.25 times it for the full sphere —
// scaled by `factor`, for both the Chebyshev degrees (the full sphere keeps half of them, those of one parity) and lmax.
struct Truncation {
  int radial = 0, lmax = 0;
};
Truncation default_truncation(double ekman, double inner_radius, int m, double factor = 1.0);

// The pencil as the viscous solver's block-form matrices (viscous_forms.hpp), each rank holding its own rows; the
// coupling vector is zero (shell_response.hpp sets the tilt's).
ViscousForms shell_forms(const ShellPencil& pencil, MPI_Comm comm);

// The damped modes closest to `target` (λ of e^{iλt}; the spin-over mode is near 1), sorted by distance, each with
// its normwise backward error as `residual`. Throws std::runtime_error when the solver fails or finds none.
std::vector<ViscousMode> shell_modes_near(const ShellSettings& settings, std::complex<double> target, int pairs,
                                          MPI_Comm comm);

}  // namespace rc::modes::spherical
