// The viscous fluid's response reduced on a rational Krylov space whose expansion points are chosen greedily
// (docs/viscous.md, "Krylov response table"): tables in seconds instead of hundreds of forced solves.
//
// At an expansion point s_i one MUMPS factorisation of S(s_i) = s_i𝓜 − A gives, by back-substitutions only (about
// 1/30 of a factorisation each), the Krylov vectors S⁻¹f, (S⁻¹𝓜)S⁻¹f, …: a shift-and-invert Krylov space, which holds
// the damped modes nearest s_i and the forced solutions x(s) = S(s)⁻¹f for s near s_i. The basis X (𝓜-orthonormal,
// over every point) carries two reduced models of R(s) = π fᵀS(s)⁻¹f:
//   R_G(s) = π fᵀX (Xᴴ S(s) X)⁻¹ Xᴴf   the Hermitian (Galerkin) projection: passive, it becomes the table;
//   R_B(s) = π fᵀX (Xᵀ S(s) X)⁻¹ Xᵀf   the bilinear one: A and 𝓜 are complex symmetric (viscous_forms.hpp), so the
//                                        dual problem Sᵀy = f is the primal one and R_B's error is quadratic in the
//                                        basis's error.
// R_B − R_G = π x_Bᵀ r_G (x_B = X c_B, r_G the Galerkin residual) is the dual-weighted residual estimate of R_G's
// error, at O(m²) per frequency (reduced_transfer.hpp). The next expansion point is the candidate frequency where
// it is largest; a forced solve there measures R_G's true error before the point is added.
// Forms with a free surface have a second input, the offset coupling g (viscous_forms.hpp): every point then adds the
// Krylov vectors of S⁻¹g too, R is the 2 × 2 matrix of R_ff, R_fg, R_gg, and the estimate and the checks are taken
// entry by entry against each entry's scale (docs/viscous.md, "Response tables of a partially filled tank").
#pragma once

#include "galerkin_projection.hpp"
#include "viscous_forms.hpp"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct KrylovOptions {
  double tolerance = 1e-6;    // stop when the estimate is below this × max|R| on the window
  // … and, when positive, when on the window Im R's estimated error is below this × Im R itself (the dissipation sets
  // a chain root's decay, and far from a resonance it is a small part of R: docs/viscous.md, "Krylov response table",
  // "The error of Im R"). Where Im R is below dissipation_floor × its largest value on the window the error is
  // measured against that floor. 0: Im R's error is measured and reported, not a stopping criterion.
  double dissipation_tolerance = 0;
  double dissipation_floor = 1e-4;
  int vectors_per_point = 8;  // Krylov vectors per expansion point (one factorisation, this many back-substitutions)
  int max_points = 100;       // expansion points (factorisations) at most
  // Complex frequencies where R_G must be R itself (a chain's roots: chain-rom confirm --refine-tables): each is an
  // expansion point before the greedy search, so x(s) lies in the basis and the Hermitian projection returns it
  // exactly (R_G(s) = R(s) to rounding). Not counted in max_points.
  std::vector<std::complex<double>> exact_at;
};

struct KrylovReduction {
  GalerkinMatrices projection;        // the Hermitian projection on the basis: reduce_on_span gives the table's rows
  std::vector<double> points;         // expansion points, in the order chosen (exact_at's are not listed)
  std::vector<double> point_errors;   // |R(s) − R_G(s)| / scale just before s was added (the first ones: NaN)
  double estimate = 0;                // max over the candidates of |R_B − R_G| / scale, final basis
  double dissipation_estimate = 0;    // max over the window of |Im(R_B − R_G)| / max(Im R_G, floor), final basis
  // … that estimate at each window frequency, in the window's order, and at the check point (when in the window)
  // at least the error measured there: what a chain root at that frequency may take from the fit in its decay
  std::vector<double> dissipation_profile;
  double check_point = 0;             // a forced solve at the final worst candidate, not added to the basis:
  double check_error = 0;             //   |R − R_G| / scale there
  double check_dissipation_error = 0; //   and |Im(R − R_G)| / max(Im R_G, floor)
  double scale = 0;                   // max |R_G| over the window's candidates
  int vectors = 0;                    // basis size
  bool within_tolerance = true;       // false: max_points reached first (estimate and check_error say how far)
};

// Chooses expansion points among `window` (real frequencies, increasing) and `beyond` (the tail) until the estimate
// is below options.tolerance, or max_points are used (then within_tolerance is false). Throws std::runtime_error with
// a one-line cause when a solve fails.
KrylovReduction krylov_reduction(const ViscousForms& forms, const std::vector<double>& window,
                                 const std::vector<double>& beyond, const KrylovOptions& options,
                                 const std::function<void(const std::string&)>& progress = {});

}  // namespace rc::modes
