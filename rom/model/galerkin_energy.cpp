#include "galerkin_energy.hpp"

#include "energy.hpp"

#include <cmath>
#include <stdexcept>

namespace rc::rom {
namespace {
using cd = std::complex<double>;
}

std::string galerkin_energy_unavailable(const ChainModel& m) {
  for (int k = 0; k < m.n; ++k) {
    const BodyModel& b = m.bodies[k];
    if (b.omega != m.bodies[0].omega)
      return "the bodies spin at different rates (an energy that balances the fluid's dissipation needs one spin)";
    if (b.has_fluid && b.ekman > 0 && b.fluid_energy.size() == 0)
      return "body " + std::to_string(k + 1) + "'s tank is " +
             (b.fit_hi > b.fit_lo ? std::string("a response fit") : std::string("a modal viscous tank")) +
             ", whose fluid holds no energy of its own (reduction = \"galerkin\" gives one, with a damped-mode table "
             "or a Galerkin response table)";
  }
  return {};
}

GalerkinEnergyMeter::GalerkinEnergyMeter(const ChainModel& m) : m_(m) {
  const std::string why = galerkin_energy_unavailable(m);
  if (!why.empty()) throw std::logic_error("no Galerkin energy: " + why);
  omega_ = m.n > 0 ? m.bodies[0].omega : 0.0;
  Eigen::MatrixXd Mp = m.M, Kp = m.K;
  for (int k = 0; k < m.n; ++k) Mp(k, k) -= m.bodies[k].E_rem;
  Kp -= omega_ * omega_ * Mp;
  for (int k = 0; k < m.n; ++k) Kp(k, k) += omega_ * omega_ * m.bodies[k].C;
  M_ = Mp.cast<cd>();
  K_ = Kp.cast<cd>();
  K_abs_ = symmetric_abs(Kp).cast<cd>();
  D_ = m.D.cast<cd>();
  for (int k = 0, first = 0; k < m.n; ++k) {
    int count = 0;
    while (first + count < m.n_modes() && m.modes[first + count].body == k) ++count;
    if (count == 0) continue;
    Tank t{k, first, m.bodies[k].fluid_energy, m.bodies[k].fluid_dissipation};
    if (t.energy.size() == 0) {  // an ideal tank: orthogonal modes (galerkin_fluid.hpp)
      Eigen::VectorXd E(count);
      for (int l = 0; l < count; ++l) E[l] = m.modes[first + l].E;
      t.energy = E.asDiagonal().toDenseMatrix().cast<cd>();
      t.dissipation = Eigen::MatrixXcd::Zero(count, count);
    }
    tanks_.push_back(std::move(t));
    first += count;
  }
}

EnergySample GalerkinEnergyMeter::operator()(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
                                             const Eigen::VectorXcd& z) const {
  const Eigen::VectorXcd W = v + cd(0, omega_) * u;
  EnergySample s;
  const double kinetic = 0.5 * W.dot(M_ * W).real();  // dot() conjugates its left side
  const double potential = 0.5 * u.dot(K_ * u).real();
  s.energy = kinetic + potential;
  s.scale = std::abs(kinetic) + 0.5 * u.dot(K_abs_ * u).real();
  s.joint_power = W.dot(D_ * v).real();
  for (const Tank& t : tanks_) {
    const auto zk = z.segment(t.first, t.energy.rows());
    cd h = 0;  // the fluid's relative angular momentum Σ Ẽ z
    for (Eigen::Index l = 0; l < zk.size(); ++l) h += m_.modes[t.first + l].E_c() * zk[l];
    const double fluid = 0.5 * zk.dot(t.energy * zk).real(), cross = (std::conj(h) * W[t.body]).real();
    s.energy += fluid + cross;
    s.scale += fluid + std::abs(cross);
    s.fluid_dissipation += zk.dot(t.dissipation * zk).real();
  }
  return s;
}

EnergyBalance energy_balance(const std::vector<EnergySample>& samples, double h) {
  EnergyBalance b;
  double dissipated = 0, scale = 0, worst = 0;
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const EnergySample& s = samples[j];
    if (j > 0) {
      const EnergySample& p = samples[j - 1];
      dissipated += 0.5 * h * (p.joint_power + p.fluid_dissipation + s.joint_power + s.fluid_dissipation);
      b.fluid_dissipated += 0.5 * h * (p.fluid_dissipation + s.fluid_dissipation);
    }
    b.energy.push_back(s.energy);
    b.joint_power.push_back(s.joint_power);
    b.fluid_dissipation.push_back(s.fluid_dissipation);
    b.dissipated.push_back(dissipated);
    scale = std::max(scale, s.scale);
    worst = std::max(worst, std::abs(s.energy - samples[0].energy + dissipated));
  }
  b.residual = scale > 0 ? worst / scale : 0.0;
  return b;
}

}  // namespace rc::rom
