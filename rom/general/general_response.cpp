#include "general_response.hpp"

#include "general_system.hpp"
#include "periodic_response.hpp"

#include <cmath>
#include <complex>
#include <limits>

namespace rc::rom {

using cd = std::complex<double>;

void mark_resonances(const GeneralChain& g, double from, double to, GeneralFrequencyResponse& r) {
  for (const cd root : general_spectrum(g).roots) {
    const double at = root.real() - g.spin;
    if (at >= std::min(from, to) && at <= std::max(from, to)) {
      r.resonances.push_back(at);
      r.resonance_growth.push_back(g.dissipative ? -root.imag() : 0.0);
    }
  }
}

GeneralFrequencyResponse general_frequency_response(const GeneralChain& g, int body, double from, double to,
                                                    int steps) {
  if (g.periodic()) return periodic_frequency_response(g, body, from, to, steps);
  const GeneralSystem sys = build_general_system(g);
  const int dim = sys.dim();
  GeneralFrequencyResponse r;
  r.body = body;
  r.tilt.resize(steps, g.n);
  r.mirror.resize(steps, g.n);
  // The force Re[e^{iΩt} (1, i)] on body K's tilt rows (unit complex moment F = 1).
  const cd I(0, 1);
  const Eigen::VectorXcd b =
      sys.input.col(2 * body).cast<cd>() + I * sys.input.col(2 * body + 1).cast<cd>();
  const Eigen::MatrixXcd B = sys.B.cast<cd>();
  for (int i = 0; i < steps; ++i) {
    const double sigma = from + (to - from) * i / (steps - 1);
    r.sigma.push_back(sigma);
    const cd omega = sigma + g.spin;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(I * omega * Eigen::MatrixXcd::Identity(dim, dim) - B);
    const Eigen::VectorXcd y = lu.solve(b);
    if (!y.allFinite()) {  // exactly at a root
      ++r.singular;
      r.tilt.row(i).setConstant(cd(std::numeric_limits<double>::quiet_NaN(), 0));
      r.mirror.row(i).setConstant(cd(std::numeric_limits<double>::quiet_NaN(), 0));
      continue;
    }
    for (int k = 0; k < g.n; ++k) {
      const cd qx = y[2 * k] / sys.s, qy = y[2 * k + 1] / sys.s;
      r.tilt(i, k) = 0.5 * (qx - I * qy);
      r.mirror(i, k) = 0.5 * std::conj(qx + I * qy);
    }
  }
  mark_resonances(g, from, to, r);
  return r;
}

}  // namespace rc::rom
