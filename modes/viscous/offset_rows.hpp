// A partially filled tank's response about a point at height −c below the liquid's centroid is R(c) = R_ff + 2c R_fg
// + c² R_gg (docs/physics.md §2, "Partially filled tanks"), and a mode contributes 2(a + c t)²/(σ − λ): a rank-one
// residue matrix. A reduced model's pole (a Ritz value of the Krylov or Galerkin response table) has a symmetric
// residue matrix of rank two in general; written as two rank-one terms, it becomes two table rows with that pole, each
// read by chain-rom as any partially filled tank's mode (docs/viscous.md, "Response tables of a partially filled tank").
#pragma once

#include "mode_table.hpp"

#include <array>
#include <complex>

namespace rc::modes {

// A mode's residue 2(a + c t)² as (a, t).
struct OffsetRow {
  std::complex<double> a, t;
};

// The symmetric residue matrix [[ff, fg], [fg, gg]] as two rows whose 2(a + c t)² sum to ff + 2c fg + c² gg for every
// c: the larger diagonal entry's row carries the off-diagonal, the other row the rest (its Schur complement):
// (√(ff/2), fg/(2a)) and (0, √((gg − fg²/ff)/2)), or with f and g exchanged; with both diagonals 0 (to 1e-12 of fg),
// 2c fg = 2(α + cα)² + 2(iα − icα)², α² = fg/4. Each row's a on the branch Re a ≥ 0 (t follows it), as a table's.
std::array<OffsetRow, 2> offset_rows(std::complex<double> ff, std::complex<double> fg, std::complex<double> gg);

// Appends the pole's two rows (those not both 0) to a partially filled tank's viscous table: λ + i decay = pole,
// E + i E_imag = 2a², a + i a_imag, N² = 1, `residual`, and t + i t_imag in /free_surface.
void add_offset_rows(ModeTable& t, std::complex<double> pole, std::complex<double> ff, std::complex<double> fg,
                     std::complex<double> gg, double residual);

}  // namespace rc::modes
