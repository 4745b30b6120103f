// Passivity of a response-fit tank (docs/rom.md, "Viscous tanks"): on the real axis Im R(s) >= 0 (the fluid only
// takes energy from a harmonic tilt; common/passivity_scan.hpp). A fit with Im R < 0 somewhere could feed the chain
// energy that water never would, and grow a root by itself. `spectrum` reports, per response-fit tank, the smallest
// Im R over the fit's window.
#pragma once

#include "chain_model.hpp"
#include "passivity_scan.hpp"

namespace rc::rom {

struct FitPassivity {
  bool checked = false;  // the tank has a response-fit table (fit_hi > fit_lo)
  PassivityScan scan;    // in table units
  bool passive() const { return !checked || scan.passive(); }
};

// The scan of body k's kept modes, taken back to table units.
FitPassivity fit_passivity(const ChainModel& m, int body);

}  // namespace rc::rom
