// The energy budget of a linear run with viscous tanks (docs/rom.md, "Viscous tanks", "Energy budget").
// The chain with its fluid frozen has the energy H_b = ½ u̇ᴴ M u̇ + ½ uᴴ K u (the quadratic integral of (26) without
// fluid modes: the gyroscopic terms do no work). Along any solution of (26)
//   dH_b/dt = −u̇ᴴ D u̇ − P_f,   P_f = −Re u̇ᴴ F,   F = M ü + i G u̇ + D u̇ + K u,
// F being the moments of the fluid's relative motion (all that (26) adds to the frozen chain) and P_f the power the
// fluid takes from the bodies. For a spinning chain H_b is the second variation of energy − spin × momentum, which
// has no sign, and so has the fluid's share of it: P_f is what the fluid dissipates plus the change of that share.
// A table of damped modes or a response fit describes the fluid from outside (moment against motion) and does not fix
// its share at an instant, so the fluid's dissipation rate itself is not available. Its work W(t) = ∫ P_f dt is, and
// for a scene released at rest with the fluid at relative rest that decays back to rest, W(∞) is all the fluid
// dissipated (its share is 0 at both ends).
#pragma once

#include "chain_model.hpp"
#include "first_order_system.hpp"

#include "eigen_dense.hpp"

namespace rc::rom {

struct BudgetSample {
  double frozen_energy = 0;   // H_b (J)
  double fluid_power = 0;     // P_f (W), taken by the fluid from the bodies
  double friction_power = 0;  // u̇ᴴ D u̇ (W)
  double scale = 0;           // ½ u̇ᴴ M u̇ + ½ uᴴ |K| u: the size the balance is measured against
};

// Evaluates the budget at balanced states y of build_first_order (ü from the system itself).
class BudgetMeter {
 public:
  BudgetMeter(const ChainModel& m, const FirstOrderSystem& f);
  BudgetSample operator()(const Eigen::VectorXcd& y) const;

 private:
  const ChainModel& m_;
  const FirstOrderSystem& f_;
  Eigen::MatrixXcd accel_;  // the rows of B that give ü
  Eigen::MatrixXd K_abs_;
};

struct EnergyBudget {
  std::vector<double> frozen_energy, fluid_power, friction_power;
  std::vector<double> fluid_work;     // W(t) = ∫_0^t P_f dt by the trapezoidal rule on the output samples (J)
  double friction_work = 0;           // ∫_0^T u̇ᴴ D u̇ dt over the run (J)
  // max_t |H_b(t) − H_b(0) + ∫_0^t (P_friction + P_f) dt| / max_t scale: the balance checked numerically on the
  // output samples (trapezoidal rule: its own error falls as the output step squared)
  double balance_residual = 0;
  bool empty() const { return frozen_energy.empty(); }
};

// Integrates the powers of `samples` (one per output time t_j = j h) and measures the balance.
EnergyBudget energy_budget(const std::vector<BudgetSample>& samples, double h);

}  // namespace rc::rom
