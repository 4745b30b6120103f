// `chain-rom run` with `[run] model = "nonlinear"` (docs/rom.md, "Nonlinear chain"): the scene's chain as
// nonlinear_chain.hpp's bodies and tanks, its initial state from the scene's Krylov angles, rates and spins, and the
// Lie-group Dormand–Prince integration with error control, sampled at run.output_step.
#pragma once

#include "nonlinear_chain.hpp"
#include "propagation.hpp"
#include "scene.hpp"

namespace rc::rom {

// The chain of a scene: totals with the frozen fluid, moments (B defaults to A), joints, and each tank's kept modes,
// ideal or viscous (plus its static correction as a mode of λ = 0).
NonlinearChain nonlinear_chain(const Scene& scene);

// Body k released with u_k = β_k − iα_k (Krylov angles): attitude R_x(−α_k) R_y(β_k), so that its axis is
// n_k = (sin β, sin α cos β, cos α cos β) and u_k = n_x − i n_y to third order. That sign of α is the one of
// Kononov's linearised equations (25): with it a spin ω_k0 about +n_k gives their gyroscopic terms
// A′β̈ + Cω0 α̇ and A′α̈ − Cω0 β̇ (checked by the small-amplitude test). The rate u̇_k = β̇ − iα̇ gives the transverse
// angular velocity −α̇ e_x + β̇ R_x(−α) e_y, and the spin ω_k0 is the axial component Ω_k·n_k. A free chain starts
// with its centre of mass at rest.
ChainState nonlinear_initial_state(const Scene& scene, const NonlinearChain& chain);

// The tilt of every body as the linear model defines it, u_k = n_x − i n_y of its axis.
Eigen::VectorXcd nonlinear_tilts(const ChainState& state);

struct NonlinearHistory {
  History base;                      // t, u (tilts), H (energy), drift, timing; z empty
  std::vector<double> quaternions;   // per sample: (w, x, y, z) of every body, body → space
  std::vector<double> spins;         // per sample: Ω_k·n_k of every body (rad/s)
  std::vector<double> momentum;      // per sample: total angular momentum about O_1's start (3 components)
  std::vector<std::complex<double>> zeta;  // per sample: the fluid coordinates (rad/s), body by body
  int fluid_modes = 0;
  // With fluid the chain has no energy integral of the bodies alone (the fluid's relative motion carries energy
  // the modal model does not write as one): energy and momentum drifts are then not reported.
  bool integrals_valid = true;
  // The angular momentum with the liquid's relative part is an integral when every tank rides by volume_fluid.hpp
  // (the axisymmetric tank model leaves out the axial part of Ω × h).
  bool momentum_valid = true;
  double max_momentum_drift = 0;     // max |L − L(0)| / |L(0)| (free chain), max |L_z − L_z(0)| / |L(0)| (fixed)
  long rejected_steps = 0;
  // Largest |r − r_table| / |r_table| of a body with a viscous tank: its table holds for the Ek of the scene's spin,
  // and the modes are scaled with the spin as if Ek stayed (docs/rom.md, "Nonlinear chain", "Viscous tanks").
  double viscous_spin_change = 0;
  bool viscous_tanks = false;
};

// Integrates to run.t_end by the Lie-group Dormand–Prince 5(4) (nonlinear_chain.hpp, chain_step_dp) with error
// control: the local error estimate (the attitudes in rad, the rates and fluid coordinates relative to max(1 rad/s, the
// largest |ω|)) must stay under run.tolerance. Throws std::runtime_error past kMaxIntegratorSteps steps, on a step
// below 1e-13 s, or on a non-finite state.
NonlinearHistory integrate_nonlinear(const NonlinearChain& chain, const ChainState& initial, const RunSpec& run);

}  // namespace rc::rom
