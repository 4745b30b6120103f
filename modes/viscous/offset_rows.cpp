#include "offset_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rc::modes {

using cd = std::complex<double>;

std::array<OffsetRow, 2> offset_rows(cd ff, cd fg, cd gg) {
  std::array<OffsetRow, 2> rows;
  if (std::max(std::abs(ff), std::abs(gg)) <= 1e-12 * std::abs(fg)) {
    const cd alpha = 0.5 * std::sqrt(fg);
    rows = {OffsetRow{alpha, alpha}, OffsetRow{cd(0, 1) * alpha, cd(0, -1) * alpha}};
  } else if (std::abs(ff) >= std::abs(gg)) {
    const cd a = std::sqrt(ff / 2.0);
    rows = {OffsetRow{a, fg / (2.0 * a)}, OffsetRow{0.0, std::sqrt((gg - fg * fg / ff) / 2.0)}};
  } else {
    const cd t = std::sqrt(gg / 2.0);
    rows = {OffsetRow{fg / (2.0 * t), t}, OffsetRow{std::sqrt((ff - fg * fg / gg) / 2.0), 0.0}};
  }
  for (OffsetRow& r : rows)
    if (r.a.real() < 0 || (r.a.real() == 0 && r.a.imag() < 0)) r = {-r.a, -r.t};
  return rows;
}

void add_offset_rows(ModeTable& t, cd pole, cd ff, cd fg, cd gg, double residual) {
  for (const OffsetRow& row : offset_rows(ff, fg, gg)) {
    if (row.a == 0.0 && row.t == 0.0) continue;
    const cd E = 2.0 * row.a * row.a;
    t.lambda.push_back(pole.real());
    t.kappa.push_back(2 / pole.real());
    t.decay.push_back(std::max(pole.imag(), 0.0));  // ≥ 0 up to rounding: a passive reduction's poles
    t.E.push_back(E.real());
    t.E_imag.push_back(E.imag());
    t.a.push_back(row.a.real());
    t.a_imag.push_back(row.a.imag());
    t.N2.push_back(1.0);
    t.residual.push_back(std::max(residual, std::numeric_limits<double>::epsilon()));
    t.free_surface.t.push_back(row.t.real());
    t.free_surface.t_imag.push_back(row.t.imag());
  }
}

}  // namespace rc::modes
