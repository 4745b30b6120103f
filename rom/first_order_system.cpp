#include "first_order_system.hpp"

#include <cmath>

namespace rc::rom {

FirstOrderSystem build_first_order(const ChainModel& m) {
  using cd = std::complex<double>;
  const cd I(0, 1);
  FirstOrderSystem f;
  const int n = m.n, nm = m.n_modes();
  f.n = n;
  f.nm = nm;
  Eigen::LDLT<Eigen::MatrixXd> ldlt(m.M_eff);
  const Eigen::MatrixXd MiK = ldlt.solve(m.K);
  Eigen::VectorXd Gamma = m.G;  // Gamma_k = C_k w_k0 - sum_l E_kl lambda_kl
  for (const auto& md : m.modes) Gamma[md.body] -= md.E * md.lambda;

  // Frequency scale: sqrt(|M^-1 K|) if there is stiffness, else the gyroscopic/fluid rates.
  double s = std::sqrt(MiK.norm());
  if (!(s > 0)) s = ldlt.solve(Eigen::MatrixXd(Gamma.asDiagonal())).norm();
  if (!(s > 0))
    for (const auto& md : m.modes) s = std::max(s, std::abs(md.nu));
  if (!(s > 0) || !std::isfinite(s)) s = 1;
  f.s = s;

  const int D = 2 * n + nm;
  f.B.setZero(D, D);
  // (s u)' = s u-dot
  f.B.block(0, n, n, n) = cd(s) * Eigen::MatrixXcd::Identity(n, n);
  // M_eff u'' = -K u - (i Gamma + D) u' + i sum E nu w      [(26) with (21) substituted]
  Eigen::MatrixXcd Cdamp = (I * Eigen::MatrixXd(Gamma.asDiagonal())).eval() + m.D.cast<cd>();
  f.B.block(n, 0, n, n) = (-MiK / s).cast<cd>();
  Eigen::MatrixXd Minv = ldlt.solve(Eigen::MatrixXd::Identity(n, n));
  f.B.block(n, n, n, n) = -(Minv.cast<cd>() * Cdamp);
  for (int l = 0; l < nm; ++l) {
    const FluidMode& md = m.modes[l];
    f.B.block(n, 2 * n + l, n, 1) = (I * md.E * md.nu) * Minv.col(md.body).cast<cd>();
    // w' = -i nu w - i lambda u'      [fluid equation of (26) in w = z + u-dot]
    f.B(2 * n + l, n + md.body) = -I * md.lambda;
    f.B(2 * n + l, 2 * n + l) = -I * md.nu;
  }
  return f;
}

Eigen::VectorXcd FirstOrderSystem::to_state(const ChainModel& m, const Eigen::VectorXcd& u,
                                            const Eigen::VectorXcd& v,
                                            const Eigen::VectorXcd& z) const {
  Eigen::VectorXcd y(dim());
  y.head(n) = s * u;
  y.segment(n, n) = v;
  for (int l = 0; l < nm; ++l) y[2 * n + l] = z[l] + v[m.modes[l].body];
  return y;
}

void FirstOrderSystem::from_state(const ChainModel& m, const Eigen::VectorXcd& y,
                                  Eigen::VectorXcd& u, Eigen::VectorXcd& v,
                                  Eigen::VectorXcd& w) const {
  u = y.head(n) / s;
  v = y.segment(n, n);
  w = y.tail(nm);
}

}  // namespace rc::rom
