// Characteristic roots sigma (solutions e^{i sigma t}, Kononov) as eigenvalues of the first-order
// system — never by polynomial root finding from scratch (maps track roots from a neighbouring point's eigen-roots,
// root_tracking.hpp) — with the stability verdict, the margin, the owner of each root and the cross-check against
// det Phi(sigma) = 0 of (22)/(29).
#pragma once

#include "chain_model.hpp"
#include "first_order_system.hpp"
#include "fit_passivity.hpp"
#include "krein_gap.hpp"
#include "verdict.hpp"

#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace rc::rom {

struct Root {
  std::complex<double> sigma;  // rad/s
  std::string owner;           // "body 2" or "fluid 1.3" (body 1, kept mode 3)
  double residual = 0;         // scaled det residual; NaN where (22) is undefined
  // Newton on det Phi = 0 started here (root_newton.hpp): |sigma_Newton - sigma| / spectral radius;
  // NaN where (22) is undefined or Newton did not converge.
  double newton_shift = 0;
  bool outside_fit = false;        // some tank's response fit is extrapolated at this root (Spectrum::outside_fit)
  // The largest of the tanks' Krylov-table Im R errors at this root's frequency (BodyModel::fit_decay_error_at): what
  // the tables' fit alone may take from its decay, relative; −1 where no table gives it.
  double fit_decay_error = -1;
  bool unconverged_owner = false;  // owned by a cluster its table flags as not converged (docs/cones.md)
  // With companion tables (companion_check.hpp): the relative distance to the nearest root computed with them, and
  // whether that passes kCompanionTolerance. NaN and false without companions.
  double companion_shift = std::numeric_limits<double>::quiet_NaN();
  // The relative change of the growth or decay rate -Im sigma (NaN for a root on the real axis).
  double companion_rate_shift = std::numeric_limits<double>::quiet_NaN();
  bool companion_moved = false;
};

struct Spectrum {
  std::vector<Root> roots;     // sorted by Re sigma, then Im sigma
  AxialSpectrum axial;         // the spins' own roots (axial_rotation.hpp), apart from (26)'s and from the verdict
  double tolerance = 0;        // |Im sigma| <= tolerance counts as real
  bool stable = false;         // no friction: all roots real; friction: no growing root
  double margin = 0;           // largest |Im sigma|; friction or viscous fluid: the largest growth rate
  double growth = 0;           // largest -Im sigma (> noise with dissipation: a growing solution; < 0: every root decays)
  double noise = 0;            // with dissipation: growth below it is rounding (Verdict::noise)
  int growing = 0, at_zero = 0;  // with dissipation: roots that grow; roots at sigma = 0 within the tolerance
  double det_residual = 0;     // worst scaled residual over the roots where (22) is defined
  int unchecked = 0;           // roots at sigma = 0 or at a pole of (22)
  double root_agreement = 0;   // worst newton_shift: eigen-roots of (26) against Newton on (22)
  int newton_failed = 0;       // roots where (22) is defined but Newton did not converge
  int nonreal = 0;             // roots with |Im sigma| > tolerance
  // Roots where some tank's response-fit table is extrapolated: Re (sigma + omega_k)/omega_k outside its window.
  int outside_fit = 0;
  int unconverged_owners = 0;  // roots owned by a kept cluster that its table flags as not converged
  // The Sturm-type certificate of an undamped chain (real_root_certificate.hpp): real roots proven by sign changes,
  // out of certificate_roots (the roots away from σ = 0). Not applied (certificate_roots = -1) with dissipation.
  int certified_real = 0, certificate_roots = -1, roots_at_zero = 0;
  // A stable undamped chain's distance to the threshold (krein_gap.hpp); not defined otherwise.
  KreinGap krein;
  bool certificate_disagrees() const {
    if (certificate_roots < 0) return false;
    return stable != (certified_real == certificate_roots);
  }
  // Per body: the passivity of its response-fit tank on the fit's window (fit_passivity.hpp; checked = false for
  // other tanks), and how many fits dip below Im R = 0.
  std::vector<FitPassivity> passivity;
  int fits_not_passive = 0;
  bool companion_checked = false;  // the roots were recomputed with the companion tables
  int companion_moved = 0;         // roots that moved past kCompanionTolerance
  double companion_worst = 0;      // the largest relative move of a root the verdict rests on
  double companion_worst_rate = 0; // the largest relative change of such a root's growth or decay rate
};

Spectrum compute_spectrum(const ChainModel& m);
Verdict compute_verdict(const ChainModel& m);
// What compute_verdict does in two steps, for callers that find the roots another way (root_tracking.hpp): the
// roots by the eigen-solver (no eigenvectors), and the verdict of a complete set of roots.
Eigen::VectorXcd verdict_roots(const ChainModel& m);
Verdict verdict_from_roots(const ChainModel& m, const Eigen::VectorXcd& sigma);

}  // namespace rc::rom
