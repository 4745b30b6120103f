// Damped inertial modes near a real target: SLEPc's Krylov–Schur with shift-and-invert on the real block
// pencil (Â, M̂) of viscous_forms.hpp, MUMPS LU of Â − σM̂ (distributed under mpirun).
//
// A real shift serves because the wanted eigenvalues λ = λ_r + i·decay lie near the real axis (decay ~ Ek^{1/2}
// for the modes that continue the ideal ones); each appears with its conjugate, the eigenvalue of the conjugate
// problem, which is dropped (docs/viscous.md, "Why a real block form").
#pragma once

#include "viscous_forms.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

struct ViscousMode {
  std::complex<double> lambda;    // e^{iλt}: Re λ the frequency in the rotating frame, Im λ = decay ≥ 0
  std::complex<double> residue;   // E_c = π (fᵀx)² / xᵀ𝓜x (bilinear, unconjugated): the coupling whose Ek → 0
                                  // limit is the ideal E (viscous_forms.hpp)
  double residual = 0;            // SLEPc's relative residual ‖Âx − λM̂x‖ / (|λ| ‖x‖)
};

struct ViscousSolveSettings {
  int pairs = 2;             // complex eigenvalues wanted near the target (each comes with its conjugate)
  double tolerance = 1e-10;  // SLEPc's relative tolerance
  int max_iterations = 500;
};

// The damped modes closest to the real target σ, sorted by distance from it. Throws std::runtime_error when
// SLEPc fails, converges to fewer than one physical pair, or the factorisation is singular.
std::vector<ViscousMode> viscous_modes_near(const ViscousForms& forms, double target,
                                            const ViscousSolveSettings& settings);

}  // namespace rc::modes
