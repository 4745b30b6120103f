#include "first_order_system.hpp"

#include "base_translation.hpp"

#include <cmath>

namespace rc::rom {

template <class Real>
Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic> first_order_matrix(const ChainModel& m, Real s) {
  // A free chain with a partially filled tank: the chain with its base's translation, reduced (base_translation.hpp).
  if (m.extended) return reduce_first_order(m, first_order_matrix(*m.extended, s), s);
  using C = std::complex<Real>;
  using RMat = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using CMat = Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic>;
  const C I(0, 1);
  const int n = m.n, nm = m.n_modes(), D = 2 * n + nm;
  // M_eff^{-1}: real (LDL^T) unless a viscous tank's kept residues leave an imaginary part on it.
  CMat Minv, MiK;
  if (m.M_eff_imag.cwiseAbs().maxCoeff() == 0) {
    const Eigen::LDLT<RMat> ldlt(m.M_eff.cast<Real>());
    Minv = ldlt.solve(RMat::Identity(n, n)).template cast<C>();
    MiK = ldlt.solve(m.K.cast<Real>()).template cast<C>();
    if (m.has_circulatory())  // the Magnus moments: K − i diag(circulatory)
      for (int k = 0; k < n; ++k) MiK.col(k) -= I * Real(m.circulatory[k]) * Minv.col(k);
  } else {
    const CMat Mc = m.M_eff.cast<Real>().template cast<C>() + I * m.M_eff_imag.cast<Real>().template cast<C>();
    const Eigen::PartialPivLU<CMat> lu(Mc);
    Minv = lu.inverse();
    MiK = lu.solve(m.K.cast<Real>().template cast<C>());
    if (m.has_circulatory())
      for (int k = 0; k < n; ++k) MiK.col(k) -= I * Real(m.circulatory[k]) * Minv.col(k);
  }
  // Gamma = diag(C_k w_k0) - sum_l E_kl lambda_kl w wᵀ (complex for viscous modes: E_c lambda_c; w the mode's
  // coupling row, e_k unless its joint moves: chain_model.hpp)
  CMat Gamma = CMat(m.G.cast<Real>().template cast<C>().asDiagonal());
  for (const auto& md : m.modes) add_mode_term(Gamma, md, -C(md.E_c()) * C(md.lambda_c()));

  CMat B = CMat::Zero(D, D);
  // (s u)' = s u-dot
  B.block(0, n, n, n) = C(s) * CMat::Identity(n, n);
  // M_eff u'' = -K u - (i Gamma + D) u' + i sum E nu w_row w      [(26) with (21) substituted]
  const CMat Cdamp = I * Gamma + m.D.cast<Real>().template cast<C>();
  B.block(n, 0, n, n) = -MiK / C(s);
  B.block(n, n, n, n) = -(Minv * Cdamp);
  for (int l = 0; l < nm; ++l) {
    const FluidMode& md = m.modes[l];
    CMat row = CMat::Zero(n, 1);  // the coupling row as a column
    row(md.body, 0) = static_cast<C>(md.own);
    for (const auto& [j, r] : md.lever) row(j, 0) = static_cast<C>(r);
    B.block(n, 2 * n + l, n, 1) = (I * C(md.E_c()) * C(md.nu_c())) * (Minv * row);
    // w' = -i nu w - i lambda w_rowᵀ u'      [fluid equation of (26) in w = z + w_rowᵀ u-dot]
    B.block(2 * n + l, n, 1, n) = (-I * C(md.lambda_c())) * row.transpose();
    B(2 * n + l, 2 * n + l) = -I * C(md.nu_c());
  }
  return B;
}

template Eigen::MatrixXcd first_order_matrix<double>(const ChainModel&, double);
template Eigen::Matrix<std::complex<long double>, Eigen::Dynamic, Eigen::Dynamic> first_order_matrix<long double>(
    const ChainModel&, long double);

std::complex<double> first_order_trace(const ChainModel& m) {
  if (m.extended) return first_order_matrix(m, 1.0).trace();
  using C = std::complex<double>;
  const C I(0, 1);
  const int n = m.n;
  // The same blocks as first_order_matrix: the (u-dot, u-dot) block -M_eff^{-1}(i Gamma + D) and the fluid diagonal
  // -i nu; the s u block has a zero diagonal.
  const Eigen::MatrixXcd Mc = m.M_eff.cast<C>() + I * m.M_eff_imag.cast<C>();
  Eigen::MatrixXcd Cdamp = m.D.cast<C>();
  for (int k = 0; k < n; ++k) Cdamp(k, k) += I * m.G[k];
  C trace = 0;
  for (const auto& md : m.modes) {
    add_mode_term(Cdamp, md, -I * md.E_c() * md.lambda_c());
    trace -= I * md.nu_c();
  }
  return trace - Mc.partialPivLu().solve(Cdamp).trace();
}

FirstOrderSystem build_first_order(const ChainModel& m) {
  FirstOrderSystem f;
  f.n = m.n;
  f.nm = m.n_modes();
  // The scale only balances the blocks: the real parts of M_eff and Gamma set it well enough.
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(m.M_eff);
  Eigen::MatrixXcd Gamma = m.G.cast<std::complex<double>>().asDiagonal();  // diag(C_k w_k0) - sum E lambda w wᵀ
  for (const auto& md : m.modes) add_mode_term(Gamma, md, std::complex<double>(-md.E * md.lambda));

  // Frequency scale: sqrt(|M^-1 K|) if there is stiffness, else the gyroscopic/fluid rates.
  double s = std::sqrt(ldlt.solve(m.K).norm());
  if (!(s > 0)) s = ldlt.solve(Eigen::MatrixXd(Gamma.real())).norm();
  if (!(s > 0))
    for (const auto& md : m.modes) s = std::max(s, std::abs(md.nu_c()));
  if (!(s > 0) || !std::isfinite(s)) s = 1;
  f.s = s;
  f.B = first_order_matrix<double>(m, s);
  return f;
}

Eigen::VectorXcd FirstOrderSystem::to_state(const ChainModel& m, const Eigen::VectorXcd& u,
                                            const Eigen::VectorXcd& v,
                                            const Eigen::VectorXcd& z) const {
  Eigen::VectorXcd y(dim());
  y.head(n) = s * u;
  y.segment(n, n) = v;
  const std::complex<double> base = m.extended ? base_rate_from_z(m, v, z) : 0.0;
  for (int l = 0; l < nm; ++l) y[2 * n + l] = z[l] + coupled(m.modes[l], v) + m.modes[l].lever_base * base;
  return y;
}

void FirstOrderSystem::from_state(const ChainModel& m, const Eigen::VectorXcd& y,
                                  Eigen::VectorXcd& u, Eigen::VectorXcd& v,
                                  Eigen::VectorXcd& w) const {
  u = y.head(n) / s;
  v = y.segment(n, n);
  w = y.tail(nm);
}

Eigen::VectorXcd fluid_coordinates(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w) {
  const std::complex<double> base = m.extended ? base_rate(m, v, w) : 0.0;
  Eigen::VectorXcd z(m.n_modes());
  for (int l = 0; l < m.n_modes(); ++l) z[l] = w[l] - coupled(m.modes[l], v) - m.modes[l].lever_base * base;
  return z;
}

}  // namespace rc::rom
