// Passivity of a response-fit tank (docs/rom.md, "Viscous tanks"): the fluid only takes energy from a harmonic
// tilt, so on the real axis Im R(s) = pi times its spectral density is >= 0 (docs/viscous.md, "Where it converges
// to as Ek -> 0"). A rational fit of R (R(s) ~ sum_l E_l/(s - lambda_l), docs/viscous.md "Response fit") keeps that
// only to its fit error: a fit with Im R < 0 somewhere could feed the chain energy that water never would, and grow a
// root by itself. `spectrum` reports, per response-fit tank, the smallest Im R over the fit's window.
#pragma once

#include "chain_model.hpp"

namespace rc::rom {

struct FitPassivity {
  bool checked = false;     // the tank has a response-fit table (fit_hi > fit_lo)
  double min_im = 0;        // min over the window of Im R(s) / max |R(s)| (table units)
  double at = 0;            // the s where it is smallest
  bool passive() const { return !checked || min_im >= 0; }
};

// Im R of body k's kept modes in table units, on a grid of the window: 2001 points, and 81 more about each pole on
// it, a quarter of its decay apart (R varies on that scale there).
FitPassivity fit_passivity(const ChainModel& m, int body);

}  // namespace rc::rom
