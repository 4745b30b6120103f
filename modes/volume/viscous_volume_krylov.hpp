// The viscous fluid's 3 × 3 response in a 3-D cavity, reduced on rational Krylov spaces whose expansion points are
// chosen greedily (docs/volume.md §7, "The response table"): the meridian Krylov response table (krylov_response.hpp)
// for a pencil that is neither complex symmetric nor of one input.
//
// R(s) = Fᵀ S(s)⁻¹ F, S(s) = s𝓜 − A, F = [f_x f_y f_z] (viscous_volume_forms.hpp); for a partially filled tank
// R(s) = Gᵀ S(s)⁻¹ F over its five directions, G = F̄ (viscous_fill_surface.hpp), with the same properties (JF = F,
// JG = G, J also negating and conjugating η̃). Two properties shape it:
// * Real motions. With J(v, q) = (v̄, −q̄) (the velocity conjugated, the pressure conjugated and negated) AJ = −JA and
//   JF = F, so x(−s̄) = −J x(s): R(−s̄) = −conj R(s), and the damped modes pair as (λ, H) and (−λ̄, H̄), one real motion.
//   The bases hold J-symmetric vectors only (Jx = x: real velocity, imaginary pressure — the real time-domain system),
//   so the reduced operator XᴴAX is exactly i times a real matrix K and its Ritz values pair exactly: a table keeps one
//   of each pair (Re λ > 0) and half of each self-paired one (Re λ = 0: the purely damped spin-up of the fluid).
// * No complex symmetry. Aᵀ ≠ A (the Coriolis form is antisymmetric), so the dual problem S(s)ᵀy = f is not the primal
//   one. A second basis Y of dual Krylov vectors (MUMPS's transposed solves on the same factors) gives the
//   dual-weighted residual estimate of the Galerkin model's error,
//     R − R_G = yᵀ r_G ≈ y_Dᵀ r_G,   y_D = Y d,  Yᴴ S(s)ᵀ Y d = Yᴴ F,   r_G = F − S(s) X c,
//   whose own error is the product of the two bases' errors (Grimme, "Krylov projection methods for model reduction",
//   1997: the two-sided projection's moments).
// The model kept is the Galerkin (Hermitian) projection on X, R_G(s) = bᵀ (s − iK)⁻¹ b with b = XᴴF real: passive
// (Im xᴴAx = Ek vᴴKv ≥ 0, so every Ritz value decays) and exact at the expansion points (x(s_i) lies in span X).
#pragma once

#include "viscous_volume_forms.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct VolumeKrylovOptions {
  double tolerance = 1e-4;    // stop when the estimate and its check are below this, entry by entry (scale below)
  int vectors_per_point = 4;  // Krylov vectors per input and expansion point (each gives two J-symmetric vectors)
  int max_points = 40;        // expansion points (factorisations) at most
  // Complex frequencies where R_G must be R itself (a chain's roots): expansion points before the greedy search, so
  // that x(s) and x(−s̄) lie in the basis and the Galerkin projection returns them (R_G(s) = R(s) to rounding). Not
  // counted in max_points.
  std::vector<std::complex<double>> exact_at;
};

// The Galerkin model R_G(s) = bᵀ (s − iK)⁻¹ b (K real m × m, b real m × 3 or m × 5), evaluated by a dense solve.
struct ReducedVolumeResponse {
  Eigen::MatrixXd K, b;
  Eigen::MatrixXcd operator()(std::complex<double> s) const;
};

// One real motion of the reduced fluid: the pole λ (Re λ ≥ 0, Im λ ≥ 0 its decay) and its residue H (rank one), so
// that R(s) = Σ H/(s − λ) + H̄/(s + λ̄) over the poles (pole_sum). A self-paired pole (Re λ = 0) carries half its
// residue, so that the same sum holds.
struct VolumePole {
  std::complex<double> lambda;
  Eigen::MatrixXcd H;  // 3 × 3 (a full cavity) or 5 × 5 (a partially filled tank's directions)
};
std::vector<VolumePole> volume_poles(const ReducedVolumeResponse& model);
Eigen::MatrixXcd pole_sum(const std::vector<VolumePole>& poles, std::complex<double> s);  // poles not empty

struct VolumeKrylovReduction {
  ReducedVolumeResponse model;
  std::vector<double> points;        // expansion points, in the order chosen
  std::vector<double> point_errors;  // the measured error at each point just before it was added (the first: NaN)
  double estimate = 0;               // the final estimate's largest entry, relative to its scale, over the candidates
  double check_point = 0;            // a forced solve where it is largest, not added to the basis:
  double check_error = 0;            //   the measured error there (same measure)
  Eigen::MatrixXd scale;             // entry jk's scale: √(max|R_jj| max|R_kk|) over the window
  int primal_vectors = 0, dual_vectors = 0;
  bool within_tolerance = true;      // false: max_points reached first
};

// Chooses expansion points among 0 (always the first: the spin-up), `window` (real frequencies ≥ 0, increasing) and
// `beyond` (the tail) until the estimate and a forced solve where it is largest are below options.tolerance, or
// max_points are used (then within_tolerance is false). Collective on the forms' communicator; throws
// std::runtime_error with a one-line cause when a factorisation or a solve fails.
VolumeKrylovReduction volume_krylov_reduction(const ViscousVolumeForms& forms, const std::vector<double>& window,
                                              const std::vector<double>& beyond, const VolumeKrylovOptions& options,
                                              const std::function<void(const std::string&)>& progress = {});

}  // namespace rc::modes
