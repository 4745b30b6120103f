// A response table's rational fit on its window, refined where it errs or is not passive, for any source of R(s) on
// the real axis: the finite elements' forced solves (app/cavity_response.cpp) or the sphere's spectral ones
// (spherical/shell_response.hpp). docs/viscous.md, "Response fit: the response as a table of pseudo-modes".
//
// AAA (rational_fit.hpp) is fitted on every other window sample and the tail beyond the window, and judged on the
// window samples it did not see. Where a held-out sample errs by more than the allowed error, samples are added
// halfway to its two neighbours and the fit made again (at most 6 times, up to 4 × the samples given and at least
// 400): R is resolved where it varies fast (the peaks of weakly damped modes) without sampling the whole window that
// finely. Then, since R itself is passive (Im R ≥ 0, common/passivity_scan.hpp) and the fit only to its accuracy,
// samples are added where the fit dips below 0 between samples (at most 8 rounds).
#pragma once

#include "mode_table.hpp"
#include "rational_fit.hpp"

#include <complex>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

// R at real frequencies s; `round` names the round for progress lines ("first samples", "refinement 2 (error)").
using ResponseSampler =
    std::function<std::vector<std::complex<double>>(const std::vector<double>& s, const std::string& round)>;

struct WindowedFit {
  RationalFit fit;
  double error = 0;             // max |fit − R| over the held-out window samples / max |R| on the window
  int refinements = 0;
  std::size_t samples = 0;      // on the window, after the refinements
  std::complex<double> tail_R;  // R at the tail's last frequency (s R(s) there is the residues' sum)
};

// Samples beyond the window [lo, hi] on both sides, geometric (ratio 1.5) up to 1000 × max(|lo|, |hi|, 1): R's decay
// as (its weight)/s, which a response table must follow there too.
std::vector<double> response_tail(double lo, double hi);

// The fit of R on `window` (increasing, at least 9) and `tail` (response_tail), refined as above; `note` receives a
// line per refinement. The error may still exceed `max_error` at the end: the caller refuses the table then.
WindowedFit fit_on_window(const ResponseSampler& sample, const std::vector<double>& window,
                          const std::vector<double>& tail, double max_error,
                          const std::function<void(const std::string&)>& note);

// The fit's poles and residues as a table's pseudo-modes (λ + i decay = p_j, E + i E_imag = r_j, a + i a_imag =
// √(r_j/2), N2 = 1, the fit's error as each row's residual); returns the sum of the residues.
std::complex<double> add_pseudo_modes(ModeTable& table, const RationalFit& fit, double error);

// "passive on the window (min Im R = … max|R|)" or "NOT passive …" (then also a one-line warning on stderr from the
// root rank): the fit is passive only to its accuracy, so this is reported, not enforced.
std::string passivity_phrase(const RationalFit& fit, double lo, double hi);

}  // namespace rc::modes
