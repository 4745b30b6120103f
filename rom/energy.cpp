#include "energy.hpp"

#include <cmath>
#include <limits>

namespace rc::rom {

double Energy::scale() const { return std::abs(kinetic) + potential_abs + fluid_abs; }

Eigen::VectorXd fluid_weights(const ChainModel& m) {
  Eigen::VectorXd c(m.n_modes());
  for (int l = 0; l < m.n_modes(); ++l) {
    const FluidMode& md = m.modes[l];
    const double w0 = m.bodies[md.body].omega;
    if (w0 == 0) c[l] = md.E;
    else if (md.lambda != 0) c[l] = -md.E * md.nu / md.lambda;
    else c[l] = std::numeric_limits<double>::quiet_NaN();
  }
  return c;
}

Energy energy(const ChainModel& m, const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
              const Eigen::VectorXcd& w) {
  Energy e;
  e.kinetic = 0.5 * (v.adjoint() * m.M_eff.cast<std::complex<double>>() * v)(0, 0).real();
  e.potential = 0.5 * (u.adjoint() * m.K.cast<std::complex<double>>() * u)(0, 0).real();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ks(m.K);
  Eigen::MatrixXd Kabs = ks.eigenvectors() * ks.eigenvalues().cwiseAbs().asDiagonal() *
                         ks.eigenvectors().transpose();
  e.potential_abs = 0.5 * (u.adjoint() * Kabs.cast<std::complex<double>>() * u)(0, 0).real();
  const Eigen::VectorXd c = fluid_weights(m);
  for (int l = 0; l < m.n_modes(); ++l) {
    e.fluid += 0.5 * c[l] * std::norm(w[l]);
    e.fluid_abs += 0.5 * std::abs(c[l]) * std::norm(w[l]);
  }
  return e;
}

double dissipation(const ChainModel& m, const Eigen::VectorXcd& v) {
  return -(v.adjoint() * m.D.cast<std::complex<double>>() * v)(0, 0).real();
}

}  // namespace rc::rom
