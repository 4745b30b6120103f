// Damped inertial modes near a complex target τ: SLEPc's Krylov–Schur on T = (block of A − τ𝓜)⁻¹ M̂, the
// shift-and-invert operator of a complex shift written in real arithmetic (viscous_forms.hpp; MUMPS LU,
// distributed under mpirun).
//
// The block of the complex matrix B = A − τ𝓜 acts as B on the pairs (x, −ix) and as its conjugate on the pairs
// (y, iy). So T has the eigenvalues θ = 1/(λ − τ) of the wanted problem and their conjugates, which belong to the
// conjugate problem; an eigenvector's pair structure tells which is which, and λ = τ + 1/θ. A target near the
// damped mode (the ideal λ plus a guess of its decay) makes that θ by far the largest: the Krylov–Schur iteration
// then needs few solves (docs/viscous.md, "Discretisation and solver").
#pragma once

#include "viscous_forms.hpp"

#include <complex>
#include <memory>
#include <vector>

namespace rc::modes {

struct ViscousMode {
  std::complex<double> lambda;    // e^{iλt}: Re λ the frequency in the rotating frame, Im λ = decay ≥ 0
  std::complex<double> residue;   // E_c = π (fᵀx)² / xᵀ𝓜x (bilinear, unconjugated): the coupling whose Ek → 0
                                  // limit is the ideal E (viscous_forms.hpp)
  std::complex<double> offset;    // a partially filled tank's t: a = √(π/2) fᵀx and t = √(π/2) gᵀx for xᵀ𝓜x = 1 with
                                  // Re a ≥ 0 (viscous_forms.hpp), so that a about the joint is a + c t
  double residual = 0;            // ‖A x − λ 𝓜 x‖ / (|λ| ‖x‖), computed from the matrices
  // With ViscousSolveSettings::keep_vector, on rank 0: the mode x (velocity u+, u−, u_z, then Q = iP, numbered as
  // the TaylorHoodSpace), normalised as the table (xᵀ𝓜x = 1, a = √(π/2) fᵀx with Re a ≥ 0). Empty otherwise.
  std::vector<std::complex<double>> vector;
  double conjugate_norm = 0;  // x̄ᵀ𝓜x = ∫∫ |V|² r dr dz of that normalised x (set with keep_vector)
  // With ViscousSolveSettings::keep_block: the same normalised x in the block form of viscous_forms.hpp (Re x_j, Im x_j
  // on the slots 2j, 2j + 1), distributed like the forms, for Galerkin projections (galerkin_projection.hpp).
  std::shared_ptr<PVec> block;
  // With ViscousSolveSettings::left_vectors: the left eigenvector y (Aᵀy = λ𝓜y, block form) normalised to yᵀ𝓜x = 1
  // with the `block` above, and its residual ‖Aᵀy − λ𝓜y‖ / (|λ| ‖y‖). A symmetric pencil's (the meridian's) is x
  // itself; a 3-D cavity's is not (its Coriolis term is antisymmetric), and a response's residue needs both
  // (volume/viscous_volume_modes.hpp).
  std::shared_ptr<PVec> left;
  double left_residual = 0;
};

struct ViscousSolveSettings {
  int pairs = 2;             // damped modes wanted near the target
  double tolerance = 1e-10;  // SLEPc's relative tolerance
  int max_iterations = 500;
  bool keep_vector = false;  // keep each mode's eigenvector (for --fields)
  bool keep_block = false;   // keep each mode's block vector (ViscousMode::block)
  bool left_vectors = false; // also each mode's left eigenvector (ViscousMode::left; implies keep_block)
};

// The damped modes closest to the complex target, sorted by distance from it. Throws std::runtime_error when
// SLEPc fails, converges to no physical mode, or the factorisation fails.
std::vector<ViscousMode> viscous_modes_near(const ViscousForms& forms, std::complex<double> target,
                                            const ViscousSolveSettings& settings);

}  // namespace rc::modes
