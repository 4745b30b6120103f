// Energy of the linearised chain (derivation in docs/rom.md, "energy"):
//   H = 1/2 u'^H M_eff u' + 1/2 u^H K u + 1/2 sum_kl c_kl |w_kl|^2,   w_kl = z_kl + u'_k,
//   c_kl = E_kl (lambda_kl - w_k0)/lambda_kl  (w_k0 != 0),   c_kl = E_kl  (w_k0 = 0),
//   dH/dt = - u'^H D u' <= 0.
// At w_k0 = 0 this is the energy balance (11) of Batyr (kinetic energy of shells and fluid in
// absolute motion + potential energy, friction power on the right); for spinning bodies it is the
// quadratic integral of (26) that reduces to it (the second variation of energy - w0 x momentum),
// and may be indefinite (gyroscopic stabilisation).
#pragma once

#include "chain_model.hpp"

namespace rc::rom {

struct Energy {
  double kinetic = 0, potential = 0, fluid = 0;
  double total() const { return kinetic + potential + fluid; }
  double scale() const;  // |kinetic| + |potential| + |fluid parts|: the size H is measured against
  double fluid_abs = 0;
  double potential_abs = 0;
};

// Evaluates H at many states of one model: the matrices and weights it needs (M_eff, K, |K|, c)
// are set up once here instead of at every call (|K| takes an eigen-decomposition).
class EnergyMeter {
 public:
  explicit EnergyMeter(const ChainModel& m);
  Energy operator()(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w) const;
  // N states given by the real and imaginary parts of their u (n x N), u-dot (n x N) and w
  // (n_modes x N), one state per column: H and its scale per column.
  using Part = Eigen::Ref<const Eigen::MatrixXd>;
  void block(const Part& u_re, const Part& u_im, const Part& v_re, const Part& v_im, const Part& w_re,
             const Part& w_im, double* H, double* scale) const;

 private:
  Eigen::MatrixXd M_eff_, K_, K_abs_;
  Eigen::VectorXd c_;
  // A free chain with a partially filled tank (base_translation.hpp): the kinetic energy is the extended chain's,
  // with the base's rate from the momentum; null otherwise.
  const ChainModel* base_ = nullptr;
  Eigen::MatrixXd M_eff_ext_;
};

// NaN-filled when some mode has lambda = 0 on a spinning body (no such integral then).
Energy energy(const ChainModel& m, const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
              const Eigen::VectorXcd& w);
// dH/dt = -u'^H D u' (friction power, Batyr (11)).
double dissipation(const ChainModel& m, const Eigen::VectorXcd& v);
// |S| of a real symmetric matrix (eigenvalues by their moduli): the positive form the size of an indefinite
// potential uK u is measured with.
Eigen::MatrixXd symmetric_abs(const Eigen::MatrixXd& S);
// Weights c_kl of the fluid term.
Eigen::VectorXd fluid_weights(const ChainModel& m);

}  // namespace rc::rom
