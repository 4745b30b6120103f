// Finite-element forms of the Poincaré problem on a 3-D cavity (docs/volume.md §1; the same weak form as the
// meridian one of docs/physics.md §2 without the Fourier reduction). A mode V e^{iλt} with pressure P (ω0 = 1):
//   iλV + 2ẑ × V = −∇P  ⇒  V_h = −(iλ − 2ẑ×)∇_h P / (4 − λ²),  V_z = (i/λ) P_z,
// and div V = 0 with V·n = 0, tested with q, multiplied by iλ(4 − λ²), gives the Hermitian pencil
//   λ² M P + 2λ (iG) P − 4 Kz P = 0,
//   M = ∫ ∇q·∇p,  Kz = ∫ q_z p_z,  G = ∫ (q_y p_x − q_x p_y)  (real antisymmetric: iG is Hermitian).
// Its real form for P = p_r + i p_i is the symmetric pencil of twice the size
//   λ² [M 0; 0 M] + 2λ [0 −G; G 0] − 4 [Kz 0; 0 Kz]
// whose every eigenvalue is double ((p_r, p_i) and (−p_i, p_r) are the same complex mode).
#pragma once

#include "petsc_handles.hpp"
#include "poincare_forms.hpp"
#include "volume_space.hpp"

#include <array>

namespace rc::modes {

using Tensor3 = std::array<std::array<double, 3>, 3>;

// Mass properties of the frozen fluid for ρ = 1.
struct VolumeIntegrals {
  double volume = 0;
  std::array<double, 3> centroid{};
  Tensor3 inertia{};  // about the centroid: ∫ (|r|² δ_jk − r_j r_k)
};
VolumeIntegrals integrate_volume(const VolumeSpace& space);

// This rank's share of the elements under mpirun: a contiguous range, as even as the count allows (every rank holds
// the whole mesh; the forms and the velocity space are built from each rank's share).
struct ElementRange {
  std::size_t begin = 0, end = 0;
};
ElementRange rank_elements(const VolumeSpace& space, MPI_Comm comm);

struct VolumeForms {
  PMat M, Kz, G;
};
// On `comm` (PETSC_COMM_SELF: sequential matrices; PETSC_COMM_WORLD: rows split between the ranks, each rank
// assembling its share of the elements).
VolumeForms assemble_volume_forms(const VolumeSpace& space, MPI_Comm comm = PETSC_COMM_SELF);

// The real form above (on the forms' communicator) as the axisymmetric solver's forms (Kh = M − Kz, Gc = the antisymmetric block, no coupling
// functionals): QuadraticEigenSolver solves it (every eigenvalue twice).
PoincareForms real_form_pencil(const VolumeForms& forms);

// Q(σ) = σ² M + 2σ (iG) − 4 Kz in that real form (symmetric, indefinite): the shift-and-invert surveys' matrix.
PMat shifted_real_pencil(const PoincareForms& real, double sigma);

}  // namespace rc::modes
