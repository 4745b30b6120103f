// The ideal liquid of a partially filled 3-D tank as one self-adjoint operator (docs/volume.md §8): the state
// W = (V, η) — the velocity at the quadrature points (volume_velocity.hpp) and the free surface's displacement
// outwards from the spin axis, in the trace of the pressure space — with the energy
//   ⟨W, W⟩ = ∫ |V|² dτ + b ∫_Σ |η|² dS,
// and the mode λW = A W (ω0 = 1):
//   λ V = S V + i G P,           P = −b η on Σ, and inside fixed by Gᵀ Ω (λV) = 0 there (V discretely solenoidal),
//   λ η = i M_s⁻¹ (Gᵀ Ω V)_Σ      (the kinematic condition ∂η/∂t = V·e_ρ, weakly),
// whose eigenvalues are those of the quartic pencil −λ⁴ S/b + λ²(M + 4S/b) + 2λ iG − 4 Kz (the meridian one of
// docs/physics.md §2, "Partially filled cylinder", without the Fourier reduction). η is held as ξ = Lᵀ P η,
// P M_s Pᵀ = L Lᵀ, so that the energy is a diagonal weight (b on ξ) as the block Lanczos process needs.
//
// The forcing directions (docs/volume.md §8), about P0, the point of the craft's spin axis at the liquid's centroid's
// height (r from P0):
//   rotation about e_k:  U_k = (P_D(e_k × r), (χ_k − χ̄_k)/b),  χ_k = −(ẑ × r)·(e_k × r)   (the perturbed centrifugal
//                        potential of a tilt, docs/physics.md §2 "coupling to the body", item 1);
//   offset along the axis: T̂_k = (P_D(e_k × ẑ), (r_k − r̄_k)/b), k = x, y, so that the rotation about the point
//                        O = P0 − c ẑ of the axis is U_k + c T̂_k (item 8: a body's joint anywhere on its axis);
// P_D the projection on fields discretely solenoidal inside with the surface's potential zero, χ̄ the surface mean (a
// constant surface pressure moves nothing: η has zero mean, the liquid being incompressible).
#pragma once

#include "stiffness_solver.hpp"
#include "volume_forms.hpp"
#include "volume_free_surface.hpp"
#include "volume_velocity.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <memory>

namespace rc::modes {

class FreeSurfaceDynamics;

// (A − σ)⁻¹ for a real σ off the spectrum: with y = (S − σ)⁻¹ f for the state F = (f, ζ) and Y = iP,
//   Q̃(σ) Y = −σ(σ² − 4) (Gᵀ Ω y + i E_Σ M_s ζ),   Q̃(σ) = σ² M + 2σ iG − 4 Kz − σ²(σ² − 4) S/b   (the quartic at σ),
//   V = y − (S − σ)⁻¹ G Y,   η = i Y_Σ / b,
// Q̃'s real form factorised once (MUMPS LDLᵀ: it is indefinite).
class FreeSurfaceShiftedInverse {
 public:
  FreeSurfaceShiftedInverse(const FreeSurfaceDynamics& A, double sigma);
  double sigma() const { return sigma_; }
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;

 private:
  const FreeSurfaceDynamics& A_;
  double sigma_;
  PMat Q_;
  std::unique_ptr<StiffnessSolver> solver_;
};

class FreeSurfaceDynamics {
 public:
  // `space` without a pinned node (VolumeSpace(mesh, 0, false)) on a mesh with a free surface.
  FreeSurfaceDynamics(const VolumeSpace& space, const VolumeForms& forms);

  Eigen::Index size() const { return weights_.size(); }
  Eigen::Index velocity_size() const { return velocity_.size(); }
  const Eigen::VectorXd& weights() const { return weights_; }
  const VolumeIntegrals& liquid() const { return liquid_; }
  const VolumeFreeSurface& surface() const { return surface_; }
  const VolumeVelocity& velocity() const { return velocity_; }

  // out = A in.
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;
  // P0: the spin axis's point at the centroid's height.
  std::array<double, 3> axis_point() const;
  // U_k (k = 0, 1, 2: x, y, z) and T̂_k (k = 0, 1), real; direction(j): U_0, U_1, U_2, T̂_0, T̂_1.
  static constexpr int kDirections = 5;
  Eigen::VectorXd rotation_field(int k) const;
  Eigen::VectorXd offset_field(int k) const;
  Eigen::VectorXd direction(int j) const;
  // The same state times i.
  Eigen::VectorXd times_i(const Eigen::VectorXd& w) const;
  // ⟨u, w⟩ (the real part of the complex energy product).
  double inner(const Eigen::VectorXd& u, const Eigen::VectorXd& w) const { return u.dot(weights_.cwiseProduct(w)); }
  // The surface displacement η (real and imaginary parts at the surface dofs) of a state.
  std::array<Eigen::VectorXd, 2> displacement(const Eigen::VectorXd& w) const;

 private:
  friend class FreeSurfaceShiftedInverse;
  using Cholesky = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>;
  using LDLT = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
  // φ on every dof: the given surface values, and inside M_ii φ = rhs_int − M_is φ_s.
  Eigen::VectorXd interior_solve(const Eigen::VectorXd& rhs, const Eigen::VectorXd& surface_values) const;
  // The state's ξ part from η (one real half): ξ = Lᵀ P η.
  Eigen::VectorXd xi_from_eta(const Eigen::VectorXd& eta) const;
  Eigen::VectorXd eta_from_xi(const Eigen::VectorXd& xi) const;
  // ξ for η = (χ − χ̄)/b, χ given at the surface's points.
  Eigen::VectorXd surface_potential(const std::function<double(const std::array<double, 3>&)>& chi) const;
  Eigen::VectorXd solenoidal_part(Eigen::VectorXd v) const;
  Eigen::VectorXd rotation_velocity(int k) const;  // e_k × (x − P0) at the quadrature points

  PoincareForms real_;     // the pencil's real form (M, Kz, Gc of twice the size)
  PMat surface_block_;     // [M_s 0; 0 M_s] on the surface dofs of the real form, zero elsewhere
  VolumeIntegrals liquid_;
  VolumeFreeSurface surface_;
  VolumeVelocity velocity_;
  Eigen::SparseMatrix<double> M_;
  std::vector<int> interior_;         // dofs off the surface
  std::unique_ptr<LDLT> interior_M_;  // M restricted to them (definite: the surface holds p)
  std::unique_ptr<Cholesky> surface_mass_;
  Eigen::VectorXd weights_;
  int ndof_ = 0;
};

}  // namespace rc::modes
