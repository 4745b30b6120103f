#include "frequency_response.hpp"

#include "spectrum.hpp"
#include "base_translation.hpp"

#include <cmath>
#include <limits>

namespace rc::rom {

using cd = std::complex<double>;

Eigen::MatrixXcd dynamic_stiffness(const ChainModel& m, cd sigma) {
  if (m.extended) return reduce_on_base(dynamic_stiffness(*m.extended, sigma));  // base_translation.hpp
  const cd I(0, 1);
  Eigen::MatrixXcd Z = -sigma * sigma * m.M.cast<cd>() + I * sigma * m.D.cast<cd>() + complex_stiffness(m);
  for (int k = 0; k < m.n; ++k)
    Z(k, k) += -sigma * m.G[k] + sigma * sigma * cd(m.bodies[k].E_rem, m.bodies[k].E_rem_imag);
  for (const auto& md : m.modes) {
    const double w0 = m.bodies[md.body].omega;
    add_mode_term(Z, md, sigma * sigma * (sigma + w0) * md.E_c() / (sigma + w0 - md.lambda_c()));
  }
  return Z;
}

FrequencyResponse frequency_response(const ChainModel& m, int body, double from, double to, int steps) {
  FrequencyResponse r;
  r.body = body;
  r.tilt.resize(steps, m.n);
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(m.n);
  F[body] = 1;
  for (int i = 0; i < steps; ++i) {
    const double s = from + (to - from) * i / (steps - 1);
    r.sigma.push_back(s);
    const Eigen::MatrixXcd Z = dynamic_stiffness(m, s);
    const Eigen::FullPivLU<Eigen::MatrixXcd> lu(Z);
    Eigen::VectorXcd u = Z.allFinite() && lu.isInvertible() ? Eigen::VectorXcd(lu.solve(F)) : Eigen::VectorXcd();
    if (u.size() == 0 || !u.allFinite()) {
      ++r.singular;
      r.tilt.row(i).setConstant(cd(std::numeric_limits<double>::quiet_NaN(), 0));
    } else {
      r.tilt.row(i) = u.transpose();
    }
  }
  const Eigen::VectorXcd roots = verdict_roots(m);
  for (Eigen::Index j = 0; j < roots.size(); ++j)
    if (roots[j].real() >= std::min(from, to) && roots[j].real() <= std::max(from, to)) {
      r.resonances.push_back(roots[j].real());
      // Without dissipation Im σ is rounding: the roots are real (Kononov's necessary condition for stability).
      r.resonance_growth.push_back(m.dissipative() ? -roots[j].imag() : 0.0);
    }
  return r;
}

}  // namespace rc::rom
