#include "fit_passivity.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace rc::rom {

FitPassivity fit_passivity(const ChainModel& m, int body) {
  using cd = std::complex<double>;
  FitPassivity p;
  const BodyModel& b = m.bodies[body];
  if (!(b.fit_hi > b.fit_lo) || b.omega == 0) return p;
  // Back to table units: lambda_c / |omega| with the table's decay, and E_c up to a positive factor (chain_model.cpp
  // conjugates E_c for a negative spin; undone here).
  const double w = std::abs(b.omega), sign = b.omega < 0 ? -1 : 1;
  std::vector<cd> pole, residue;
  for (const FluidMode& md : m.modes) {
    if (md.body != body) continue;
    pole.emplace_back(md.lambda_table, md.decay / w);
    residue.emplace_back(md.E, sign * md.E_imag);
  }
  if (pole.empty()) return p;
  // A uniform grid of the window, and around each pole on it its own grid over 10 decays on either side (where R
  // varies on the scale of the decay).
  std::vector<double> grid;
  for (int i = 0; i <= 2000; ++i) grid.push_back(b.fit_lo + (b.fit_hi - b.fit_lo) * i / 2000.0);
  for (const cd q : pole)
    for (int i = -40; i <= 40; ++i)
      if (const double s = q.real() + 0.25 * i * q.imag(); s >= b.fit_lo && s <= b.fit_hi) grid.push_back(s);
  double largest = 0;
  p.min_im = std::numeric_limits<double>::infinity();
  for (const double s : grid) {
    cd R = 0;
    for (std::size_t l = 0; l < pole.size(); ++l) R += residue[l] / (s - pole[l]);
    largest = std::max(largest, std::abs(R));
    if (R.imag() < p.min_im) p.min_im = R.imag(), p.at = s;
  }
  p.min_im /= std::max(largest, std::numeric_limits<double>::min());
  p.checked = true;
  return p;
}

}  // namespace rc::rom
