// The rows of a response table (the pseudo-modes of a Krylov, Galerkin or rational-fit table: docs/viscous.md) that
// no chain root needs. Such a table holds hundreds of rows, most of them poles far beyond its window or of tiny
// residue, and `spectrum`'s dense eigen-solve costs the cube of their number. A row's contribution to entry (i, j) of
// the table's R at a window frequency s is at most |2 c_i c_j / N²| / |s − p| (p its pole; the inputs' couplings
// c_f = a and a free surface's c_g = t). Rows are left out, the smallest first, while at every window frequency and
// for every entry the sum over those left out stays within both `magnitude` × fit_error × the entry's scale
// √(max|R_ii| max|R_jj|) and `dissipation` × Im R's own size there (the decays come from Im R, a small part of |R|
// away from a resonance: docs/viscous.md, "The error of Im R"). So the table's R changes on its window by a small part
// of its own fit error, and its Im R — the roots' decays — by that fraction of itself (docs/rom.md,
// "Response-fit tables").
#pragma once

#include "mode_table.hpp"
#include "scene.hpp"

#include <vector>

namespace rc::rom {

// What the left-out rows may add up to on the window: a hundredth of the fit error in R, and 1e-4 of Im R itself (so
// every decay moves by about 1e-4 of itself at most). Both chains use these (chain_model.cpp, general_tank.cpp).
inline constexpr double kPruneMagnitude = 1e-2, kPruneDissipation = 1e-4;

struct PrunedRows {
  std::vector<int> kept;  // the rows kept, in the given order
  int dropped = 0;
};

// Whether a tank's rows are pruned: a response table's, unless the scene says prune = false, names its rows (modes or
// coverage) or asks for a Galerkin tank (whose forms hold every row), or the table was made exact at given
// frequencies (`--exact-at`, what `chain-rom confirm --refine-tables` makes: there R is the forced solves' to
// rounding, which no row may spoil). Axisymmetric tables only (a 3-D table's rows couple by tensors).
bool prunable(const rc::ModeTable& t, const CavitySpec& cav);

// `rows` indexes `t`'s rows (a response-fit table: t.response_fit()).
PrunedRows prune_response_rows(const rc::ModeTable& t, const std::vector<int>& rows, double magnitude,
                               double dissipation);

}  // namespace rc::rom
