#include "offset_rows.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace rc::modes
