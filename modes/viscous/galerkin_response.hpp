// The viscous fluid reduced by a Hermitian (Galerkin) projection on a span of forced solutions x(s_j) =
// (s_j𝓜 − A)⁻¹f (docs/viscous.md, "Galerkin response table"): a table of pseudo-modes, like the rational fit's,
// that keeps an energy and dissipates it at the viscous rate, and is passive by construction.
//
// With an orthonormal basis Q of span X (QᴴGQ… from G = X̄ᵀ𝓜X's eigen-decomposition, dependent directions dropped),
// the reduced pencil is H_q = QᴴAQ with G_q = I; its Ritz pairs H_q w_l = λ_l w_l are the rows. Because the reduced
// viscous form V_q = (H_q − H_qᴴ)/(2i) is positive semi-definite, Im λ_l = w_lᴴV_q w_l ≥ 0 (no growing pseudo-mode)
// and Im R_G(s) ≥ 0 for every real s. One-sided projection interpolates: R_G(s_j) = R(s_j) at every sample whose
// solution is in the span (Grimme, "Krylov projection methods for model reduction", 1997), so the table is the
// response at its samples to the solver's accuracy, and between them to what the held-out midpoints measure.
#pragma once

#include "galerkin_projection.hpp"
#include "viscous_response.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

struct GalerkinReduction {
  std::vector<std::complex<double>> lambda;   // Ritz values (Im ≥ 0), table units
  std::vector<std::complex<double>> residue;  // R_G's residue at each: Ẽ_l = π f_l g_l, g = G′⁻¹ f̄
  Eigen::MatrixXcd gram, viscous;             // G′ = WᴴW, V′ = WᴴV_qW in the Ritz vectors' coordinates
  Eigen::VectorXcd coupling;                  // f_l = fᵀx_l of each Ritz vector x_l = Q w_l (unit 2-norm w_l)
  int dropped = 0;                            // basis directions dropped as dependent
  // A free surface (the projection's offset set): the residues of R_fg and R_gg at each Ritz value, R_fg's made
  // symmetric (docs/viscous.md, "Response tables of a partially filled tank"); empty otherwise.
  std::vector<std::complex<double>> residue_fg, residue_gg;
  // R_G's entries at s: R_ff = Σ Ẽ_l/(s − λ_l), and with a free surface R_fg, R_gg (else 0); about a point at height
  // −c below the centroid R_G = R_ff + 2c R_fg + c² R_gg.
  OffsetResponse entries(std::complex<double> s) const;
};

// The Ritz pairs of the projection `g` (project_on_modes on forced solutions). Directions of G below
// `rank_tolerance` × its largest eigenvalue are dropped (the samples' solutions are nearly dependent). Throws
// std::runtime_error when a Ritz value grows (Im λ below −1e-10 |λ|: the viscous form is not semi-definite).
GalerkinReduction reduce_on_span(const GalerkinMatrices& g, double rank_tolerance = 1e-13);

}  // namespace rc::modes
