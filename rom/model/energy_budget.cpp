#include "energy_budget.hpp"

#include "energy.hpp"

#include <algorithm>
#include <cmath>

namespace rc::rom {

BudgetMeter::BudgetMeter(const ChainModel& m, const FirstOrderSystem& f)
    : m_(m), f_(f), accel_(f.B.middleRows(f.n, f.n)), K_abs_(symmetric_abs(m.K)) {}

BudgetSample BudgetMeter::operator()(const Eigen::VectorXcd& y) const {
  Eigen::VectorXcd u, v, w;
  f_.from_state(m_, y, u, v, w);
  const Eigen::VectorXcd a = accel_ * y;  // ü
  const std::complex<double> I(0, 1);
  // F = M ü + i G u̇ + D u̇ + K u: the fluid's relative motion's moments (energy_budget.hpp).
  using C = std::complex<double>;
  const Eigen::VectorXcd F = m_.M.cast<C>() * a + I * m_.G.cast<C>().cwiseProduct(v) + m_.D.cast<C>() * v +
                             m_.K.cast<C>() * u;
  BudgetSample s;
  const double kinetic = 0.5 * v.dot(m_.M.cast<C>() * v).real();  // dot() conjugates its left side
  s.frozen_energy = kinetic + 0.5 * u.dot(m_.K.cast<C>() * u).real();
  s.fluid_power = -v.dot(F).real();
  s.friction_power = v.dot(m_.D.cast<C>() * v).real();
  s.scale = std::abs(kinetic) + 0.5 * u.dot(K_abs_.cast<C>() * u).real();
  return s;
}

EnergyBudget energy_budget(const std::vector<BudgetSample>& samples, double h) {
  EnergyBudget b;
  if (samples.empty()) return b;
  double work = 0, friction = 0, scale = 0, worst = 0;
  for (std::size_t j = 0; j < samples.size(); ++j) {
    const BudgetSample& s = samples[j];
    if (j > 0) {
      const BudgetSample& p = samples[j - 1];
      work += 0.5 * h * (p.fluid_power + s.fluid_power);
      friction += 0.5 * h * (p.friction_power + s.friction_power);
    }
    b.frozen_energy.push_back(s.frozen_energy);
    b.fluid_power.push_back(s.fluid_power);
    b.friction_power.push_back(s.friction_power);
    b.fluid_work.push_back(work);
    scale = std::max(scale, s.scale);
    worst = std::max(worst, std::abs(s.frozen_energy - samples[0].frozen_energy + work + friction));
  }
  b.friction_work = friction;
  b.balance_residual = scale > 0 ? worst / scale : 0.0;
  return b;
}

}  // namespace rc::rom
