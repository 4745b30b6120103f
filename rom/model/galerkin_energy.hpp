// The energy of a chain whose tanks hold a fluid energy of their own (Galerkin tanks, ideal tanks) and its balance
// with the joints' and the fluid's dissipation (docs/rom.md, "Galerkin tanks: energy").
//
// For bodies that share one spin ω0, with W = u̇ + iω0 u (the bodies' transverse angular velocity relative to a frame
// turning at ω0 about the fixed axis) and h_k = Σ_l Ẽ_kl z_kl (the fluid's relative angular momentum),
//   H = ½ WᴴM′W + ½ uᴴ(K + ω0² diag(C) − ω0² M′)u + Σ_k [½ z_kᴴ 𝔈_k z_k + Re(h̄_k W_k)],   M′ = M − diag(E_rem)
// is the second variation of energy − ω0 × axial angular momentum (the fluid's share: its kinetic energy relative to
// the cavity and its cross term with the cavity's motion), and along every solution of (26)
//   dH/dt = −Re(Wᴴ D u̇) − Σ_k z_kᴴ 𝔇_k z_k:
// the power of the joint moments −D u̇ on the bodies' motion W and the fluid's viscous dissipation (galerkin_fluid.hpp).
// At ω0 = 0 this is Batyr (11). With spins that differ no quadratic form of this kind balances the dissipation (the
// fluid's exchange with its body does not close body by body; measured, docs/rom.md), and the model has none.
#pragma once

#include "chain_model.hpp"
#include "first_order_system.hpp"

#include "eigen_dense.hpp"

#include <string>
#include <vector>

namespace rc::rom {

// Empty when H above exists for the model; else why not (one line).
std::string galerkin_energy_unavailable(const ChainModel& m);

struct EnergySample {
  double energy = 0;             // H (J)
  double joint_power = 0;        // Re(Wᴴ D u̇) (W): taken by the joint moments
  double fluid_dissipation = 0;  // Σ zᴴ𝔇z (W), ≥ 0
  double scale = 0;              // the size of H's parts (absolute values), what the balance is measured against
};

class GalerkinEnergyMeter {
 public:
  explicit GalerkinEnergyMeter(const ChainModel& m);  // throws std::logic_error when unavailable
  EnergySample operator()(const Eigen::VectorXcd& u, const Eigen::VectorXcd& v, const Eigen::VectorXcd& z) const;

 private:
  const ChainModel& m_;
  double omega_ = 0;
  Eigen::MatrixXcd M_, K_, K_abs_, D_;
  struct Tank {
    int body = 0, first = 0;             // its body, its first mode in z
    Eigen::MatrixXcd energy, dissipation;  // 𝔈, 𝔇 (an ideal tank: diag(E), 0)
  };
  std::vector<Tank> tanks_;
};

struct EnergyBalance {
  std::vector<double> energy, joint_power, fluid_dissipation;
  std::vector<double> dissipated;  // ∫_0^t (joint_power + fluid_dissipation) dt, trapezoidal rule on the samples (J)
  // max_t |H(t) − H(0) + dissipated(t)| / max_t scale (its own error falls as the output step squared)
  double residual = 0;
  double fluid_dissipated = 0;  // ∫_0^T fluid_dissipation dt (J)
  bool empty() const { return energy.empty(); }
};

EnergyBalance energy_balance(const std::vector<EnergySample>& samples, double h);

}  // namespace rc::rom
