#include "fit_passivity.hpp"

#include <cmath>
#include <complex>
#include <vector>

namespace rc::rom {

FitPassivity fit_passivity(const ChainModel& m, int body) {
  FitPassivity p;
  const BodyModel& b = m.bodies[body];
  if (!(b.fit_hi > b.fit_lo) || b.omega == 0) return p;
  // Back to table units: lambda_c / |omega| with the table's decay, and E_c up to a positive factor (chain_model.cpp
  // conjugates E_c for a negative spin; undone here).
  const double w = std::abs(b.omega), sign = b.omega < 0 ? -1 : 1;
  std::vector<std::complex<double>> poles, residues;
  for (const FluidMode& md : m.modes) {
    if (md.body != body) continue;
    poles.emplace_back(md.lambda_table, md.decay / w);
    residues.emplace_back(md.E, sign * md.E_imag);
  }
  if (poles.empty()) return p;
  p.scan = scan_passivity(poles, residues, b.fit_lo, b.fit_hi);
  p.checked = true;
  return p;
}

}  // namespace rc::rom
