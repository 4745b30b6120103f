#include "energy.hpp"

#include "base_translation.hpp"

#include <cmath>
#include <limits>

namespace rc::rom {

double Energy::scale() const { return std::abs(kinetic) + potential_abs + fluid_abs; }

Eigen::VectorXd fluid_weights(const ChainModel& m) {
  Eigen::VectorXd c(m.n_modes());
  for (int l = 0; l < m.n_modes(); ++l) {
    const FluidMode& md = m.modes[l];
    const double w0 = m.bodies[md.body].omega;
    // A viscous mode (complex lambda, E) has no such weight: the modal truncation keeps no fluid energy.
    if (md.decay != 0 || md.E_imag != 0) c[l] = std::numeric_limits<double>::quiet_NaN();
    else if (w0 == 0) c[l] = md.E;
    else if (md.lambda != 0) c[l] = -md.E * md.nu / md.lambda;
    else c[l] = std::numeric_limits<double>::quiet_NaN();
  }
  return c;
}

Eigen::MatrixXd symmetric_abs(const Eigen::MatrixXd& S) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
  return es.eigenvectors() * es.eigenvalues().cwiseAbs().asDiagonal() * es.eigenvectors().transpose();
}

EnergyMeter::EnergyMeter(const ChainModel& m)
    : M_eff_(m.M_eff), K_(m.K), K_abs_(symmetric_abs(m.K)), c_(fluid_weights(m)) {
  if (m.extended) {
    base_ = &m;
    M_eff_ext_ = m.extended->M_eff;
  }
}

Energy EnergyMeter::operator()(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
                               const Eigen::VectorXcd& w) const {
  Energy e;
  if (base_) {  // ½ q̇ᴴ M_eff,ext q̇ with q̇ = (u̇, Ẋ)
    Eigen::VectorXcd q(v.size() + 1);
    q << v, base_rate(*base_, v, w);
    e.kinetic = 0.5 * q.dot(M_eff_ext_ * q).real();
  } else {
    e.kinetic = 0.5 * v.dot(M_eff_ * v).real();  // dot() conjugates its left side: v^H M v
  }
  e.potential = 0.5 * u.dot(K_ * u).real();
  e.potential_abs = 0.5 * u.dot(K_abs_ * u).real();
  for (Eigen::Index l = 0; l < c_.size(); ++l) {
    e.fluid += 0.5 * c_[l] * std::norm(w[l]);
    e.fluid_abs += 0.5 * std::abs(c_[l]) * std::norm(w[l]);
  }
  return e;
}

void EnergyMeter::block(const Part& u_re, const Part& u_im, const Part& v_re, const Part& v_im,
                        const Part& w_re, const Part& w_im, double* H, double* scale) const {
  if (base_) {  // the kinetic energy needs Ẋ per state: one state at a time
    const std::complex<double> I(0, 1);
    for (Eigen::Index j = 0; j < u_re.cols(); ++j) {
      const Energy e = (*this)(u_re.col(j) + I * u_im.col(j), v_re.col(j) + I * v_im.col(j),
                               w_re.col(j) + I * w_im.col(j));
      H[j] = e.total();
      scale[j] = e.scale();
    }
    return;
  }
  // x^H S x = a^T S a + b^T S b for x = a + ib and a real symmetric S.
  const Eigen::MatrixXd Mr = M_eff_ * v_re, Mi = M_eff_ * v_im, Kr = K_ * u_re, Ki = K_ * u_im,
                        Ar = K_abs_ * u_re, Ai = K_abs_ * u_im;
  for (Eigen::Index j = 0; j < u_re.cols(); ++j) {
    const double kin = 0.5 * (v_re.col(j).dot(Mr.col(j)) + v_im.col(j).dot(Mi.col(j))),
                 pot = 0.5 * (u_re.col(j).dot(Kr.col(j)) + u_im.col(j).dot(Ki.col(j))),
                 pot_abs = 0.5 * (u_re.col(j).dot(Ar.col(j)) + u_im.col(j).dot(Ai.col(j)));
    double fl = 0, fl_abs = 0;
    for (Eigen::Index l = 0; l < c_.size(); ++l) {
      const double w2 = w_re(l, j) * w_re(l, j) + w_im(l, j) * w_im(l, j);
      fl += 0.5 * c_[l] * w2;
      fl_abs += 0.5 * std::abs(c_[l]) * w2;
    }
    H[j] = kin + pot + fl;
    scale[j] = std::abs(kin) + pot_abs + fl_abs;
  }
}

Energy energy(const ChainModel& m, const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
              const Eigen::VectorXcd& w) {
  return EnergyMeter(m)(u, v, w);
}

double dissipation(const ChainModel& m, const Eigen::VectorXcd& v) {
  return -(v.adjoint() * m.D.cast<std::complex<double>>() * v)(0, 0).real();
}

}  // namespace rc::rom
