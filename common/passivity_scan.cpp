#include "passivity_scan.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace rc {

PassivityScan scan_passivity(const std::vector<std::complex<double>>& poles,
                             const std::vector<std::complex<double>>& residues, double lo, double hi) {
  using cd = std::complex<double>;
  std::vector<double> grid;
  for (int i = 0; i <= 2000; ++i) grid.push_back(lo + (hi - lo) * i / 2000.0);
  for (const cd q : poles)
    for (int i = -40; i <= 40; ++i)
      if (const double s = q.real() + 0.25 * i * q.imag(); s >= lo && s <= hi) grid.push_back(s);
  PassivityScan p;
  p.min_im = std::numeric_limits<double>::infinity();
  double largest = 0;
  for (const double s : grid) {
    cd R = 0;
    for (std::size_t l = 0; l < poles.size(); ++l) {  // r / d as r conj(d) / |d|^2: std::complex's division guards
      const cd d = s - poles[l];                       // against overflow are most of the scan's time
      R += residues[l] * std::conj(d) / std::norm(d);
    }
    largest = std::max(largest, std::abs(R));
    if (R.imag() < p.min_im) p.min_im = R.imag(), p.at = s;
  }
  p.min_im /= std::max(largest, std::numeric_limits<double>::min());
  return p;
}

}  // namespace rc
