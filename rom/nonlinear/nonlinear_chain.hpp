// The nonlinear chain (Kononov (1999) (1)-(5), the fluid by its modes in each body's frame): n bodies joined by
// spherical joints, body k turning about its joint O_k, O_1 fixed (fixed chain) or free (free chain); gravity,
// elastic joints, joint friction about the swing and about the axis, external moments, ideal and viscous fluid tanks
// (by their modes); every body's spin is a state and may change.
// docs/rom.md, "Nonlinear chain", derives what follows and says what is kept.
//
// Newton–Euler for body k about its joint O_k (space frame), with the reaction at O_{k+1} eliminated through the
// bodies above it, F_{k+1} = Σ_{j>k} m_j (ẍ_j − g):
//   J_k Ω̇_k + Ω_k × J_k Ω_k + m_k ρ_k × r̈_k + S_k × Σ_{j>k} m_j (ẍ_j − g) = m_k ρ_k × g + τ_k,
//   r̈_k = r̈_1 + Σ_{i<k} (Ω̇_i × S_i + Ω_i × (Ω_i × S_i)),   ẍ_j = r̈_j + Ω̇_j × ρ_j + Ω_j × (Ω_j × ρ_j),
// with J_k = R_k diag(A_k, B_k, C_k) R_kᵀ about O_k, ρ_k = R_k (0, 0, c_k) the centre of mass, S_k = R_k (0, 0, s_k)
// the next joint and τ_k the joint and external moments. r̈_1 = 0 for the fixed chain; for the free chain r̈_1 is a further
// unknown with the total force Σ_j m_j (ẍ_j − g) = 0. Linear in the Ω̇ (and r̈_1): a symmetric positive definite
// system of 3n (3n + 3) equations, solved at every stage. Its small-angle limit is (26)'s M_ki (a_k s_i, A'_k).
#pragma once

#include "volume_fluid.hpp"

#include "eigen_dense.hpp"
#include <Eigen/Geometry>

#include <cmath>
#include <complex>
#include <vector>

namespace rc::rom {

// One fluid mode of a body's cavity, in the body frame (docs/rom.md, "Nonlinear chain", "Fluid"): the scaled
// coordinate ζ obeys ζ̇ = i λ ζ − i Ṗ with λ = r λ_table (r the body's current spin, Ω·e3 in the body frame) and
// P = p − i q its transverse angular velocity in the body frame; the fluid's moment on the body is
// (M_p − i M_q) = E_total Ṗ + Σ_l E_l (r − λ_l) ζ_l. This is Kononov (26)'s fluid equation written in the body frame
// (ζ = S′ e^{iω0 t} N²/a): linear in the fluid's relative motion, exact in the body's rotation.
// A viscous table's mode (docs/rom.md, "Viscous tanks") is the same with λ_table = λ + i decay and the complex
// residue E + i E_imag, both as the table gives them for a positive spin; a negative spin mirrors the flow and
// conjugates them (mode_lambda, mode_E). The table's Ekman number is kept as the spin changes (docs/rom.md,
// "Nonlinear chain", "Viscous tanks").
struct ChainFluidMode {
  std::complex<double> E = 0;             // kg m²
  std::complex<double> lambda_table = 0;  // λ/ω0 (+ i decay/ω0) of the table
};

// λ_l at spin r: r λ_table + i |r| decay_table.
inline std::complex<double> mode_lambda(const ChainFluidMode& m, double spin) {
  return {spin * m.lambda_table.real(), std::abs(spin) * m.lambda_table.imag()};
}
// E_l at spin r: E + i sign(r) E_imag.
inline std::complex<double> mode_E(std::complex<double> E, double spin) {
  return spin < 0 ? std::conj(E) : E;
}

struct ChainBody {
  double mass = 0;               // with the frozen fluid (kg)
  double A = 0, B = 0, C = 0;    // principal moments about O_k (kg m²), body axes e1, e2 and the symmetry axis e3
  double com = 0;                // O_k → centre of mass along e3 (m)
  double next_joint = 0;         // O_k → O_{k+1} along e3 (m)
  // External moment on the body (N m): `axial` about its own axis n_k, `space` fixed in space, and
  // `harmonic` · sin(2π frequency t) in space (Kononov (1) with the moments M_k(t) of Batyr (1)-(3)).
  double axial_moment = 0;
  // A projectile's aerodynamics about O_k (docs/rom.md, "A projectile's aerodynamic moments"), the yaw measured from
  // the space z axis (the flight direction): static M_α e_z × n_k (overturning for M_α > 0, |e_z × n| = sin of the
  // total yaw) and pitch damping −M_q (Ω_k − (Ω_k·n_k) n_k) on the transverse angular velocity.
  double static_moment = 0, pitch_damping = 0;
  // The Magnus moment M_p s_k (n_k − (n_k·e_z) e_z), s_k = Ω_k·n_k the spin: along the yaw's direction.
  double magnus = 0;
  Eigen::Vector3d space_moment = Eigen::Vector3d::Zero(), harmonic_moment = Eigen::Vector3d::Zero();
  double frequency = 0;          // Hz
  // External force (N), space_force + sin(2π force_frequency t) harmonic_force, at force_at (m) along e3 from O_k
  // (Batyr's F_k): its moment about O_k on this body, and through the joints' reactions S_j × F on each body below.
  Eigen::Vector3d space_force = Eigen::Vector3d::Zero(), harmonic_force = Eigen::Vector3d::Zero();
  double force_frequency = 0, force_at = 0;
  Eigen::Vector3d force(double t) const {
    return space_force + std::sin(6.283185307179586 * force_frequency * t) * harmonic_force;
  }
  // Whether moments, forces, pitch damping or Magnus act on it (the static aerodynamic moment apart: it has a
  // potential).
  bool loaded() const {
    return axial_moment != 0 || !space_moment.isZero() || (frequency > 0 && !harmonic_moment.isZero()) ||
           pitch_damping != 0 || magnus != 0 || !space_force.isZero() || (force_frequency > 0 && !harmonic_force.isZero());
  }
  std::vector<ChainFluidMode> fluid;  // the kept modes of its cavity, then the static correction's
  int kept_modes = 0;                 // how many of `fluid` are the table's kept modes
  // Σ E of the kept modes + the static correction: the transverse inertia the fluid does not carry rigidly
  // (A − E_total is the body's instantaneous inertia, as M_eff in (26)); complex for a viscous table without its
  // static correction (for a positive spin, as ChainFluidMode's E).
  std::complex<double> fluid_E_total = 0;
  double table_spin = 0;         // a viscous tank: the spin at which the scene's viscosity gives the table's Ek; else 0
  // Tanks without axial symmetry (3-D tables, tanks off the axis, several tanks; volume_fluid.hpp): their modes follow
  // the `fluid` ones in the state. Such a body's axes are its principal axes, turned by `principal_turn` (rad) about
  // e3 from the scene's (its products I_xy with the frozen liquid diagonalised; I_xz, I_yz vanish).
  VolumeFluid volume;
  double principal_turn = 0;
  // An axisymmetric tank's liquid about the symmetry axis (docs/physics.md §3, "Axial rotations"): the ideal liquid
  // does not follow the body's turns about that axis (Batyr (2010) (34)–(42): it enters the inertia through the
  // projection on potential fields, and P_G(e3 × r) = 0), so C above is the shell's and the liquid's axial momentum
  // stays liquid_axial · liquid_spin along n_k (C_f and its spin at the start: a gyrostat's constant momentum).
  double liquid_axial = 0, liquid_spin = 0;
  double liquid_momentum() const { return liquid_axial * liquid_spin; }
  int modes() const { return static_cast<int>(fluid.size()) + volume.size(); }
};

struct ChainJoint {              // joint k: O_k, between body k − 1 (the support for k = 1) and body k
  double stiffness = 0;          // κ²: bending moment κ² n_k × n_{k−1} on body k, V = κ²(1 − n_{k−1}·n_k); 0 at the support
  double friction = 0;           // α: moment −α (w_k − w_{k−1}) on the swing rates w = n × ṅ (N m s)
  double axial_friction = 0;     // moment −α_ax (s_k − s_{k−1}) along the joint's mean axis, s = Ω·n the spins
};

struct NonlinearChain {
  bool free_chain = false;
  double gravity = 0;                 // along −e3 of space (m/s²)
  // A uniform force field besides gravity (m/s², on every mass; the scene's [field]): field + sin(2π f t) field_harmonic.
  Eigen::Vector3d field = Eigen::Vector3d::Zero(), field_harmonic = Eigen::Vector3d::Zero();
  double field_frequency = 0;         // Hz
  // The field's non-uniform part G x (1/s², symmetric: a potential's), x from the space origin: on each body the force
  // m G x_c and the moment about O_k, m ρ × G O_k + Σ ε (J G) (a gravity-gradient moment), its potential
  // −½ ∫ xᵀG x dm in the energy (docs/rom.md, "A field that varies in space").
  Eigen::Matrix3d field_gradient = Eigen::Matrix3d::Zero();
  // The acceleration field every mass feels at time t: gravity and the field.
  Eigen::Vector3d acceleration(double t) const {
    return Eigen::Vector3d(0, 0, -gravity) + field + std::sin(6.283185307179586 * field_frequency * t) * field_harmonic;
  }
  std::vector<ChainBody> bodies;
  std::vector<ChainJoint> joints;     // n: joints[0] is the support (stiffness 0), joints[k] links bodies k−1 and k
  int size() const { return static_cast<int>(bodies.size()); }
  int fluid_modes() const;
};

struct ChainState {
  double t = 0;                       // time (s): the external moments depend on it
  std::vector<Eigen::Quaterniond> q;  // attitude of each body: body → space
  std::vector<Eigen::Vector3d> omega; // angular velocity of each body in its own frame (rad/s)
  Eigen::Vector3d r1 = Eigen::Vector3d::Zero(), v1 = Eigen::Vector3d::Zero();  // O_1 and its velocity (free chain)
  std::vector<std::complex<double>> zeta;  // fluid coordinates, body by body, mode by mode (rad/s; the modes of
                                           // tanks without axial symmetry after the others: z in kg^{1/2} m rad/s)
};

struct ChainRates {
  std::vector<Eigen::Vector3d> omega_dot;  // body frames
  Eigen::Vector3d a1 = Eigen::Vector3d::Zero();
  std::vector<std::complex<double>> zeta_dot;
};

// The accelerations of the equations above. Throws std::runtime_error if the mass matrix is singular (a body
// without inertia).
ChainRates chain_rates(const NonlinearChain& chain, const ChainState& state);

// Kinetic + gravitational + elastic energy (J), and the total angular momentum (kg m²/s) about the space origin
// (where O_1 starts; for the fixed chain O_1 itself).
double chain_energy(const NonlinearChain& chain, const ChainState& state);
Eigen::Vector3d chain_angular_momentum(const NonlinearChain& chain, const ChainState& state);

// The power (W) of every load the energy above does not hold (Batyr's energy balance (11), docs/rom.md, "Nonlinear
// chain"): the external moments and forces at their points (the static aerodynamic moment apart: its potential is in
// the energy), joint friction, and the field's time-varying part on every mass. dH/dt is this power for a chain without
// fluid; `nonconservative` says whether the chain has any such load.
double nonconservative_power(const NonlinearChain& chain, const ChainState& state);
bool nonconservative(const NonlinearChain& chain);
// Whether anything from outside turns the chain (its angular momentum then changes): body loads, the static
// aerodynamic moment, a transverse, harmonic or varying field. Gravity and an axial field keep a fixed chain's L_z.
bool external_loads(const NonlinearChain& chain);

// Symmetry axis n_k = R_k e3 of every body in space.
std::vector<Eigen::Vector3d> chain_axes(const ChainState& state);

// One RKMK4 step (rigid_body.hpp's Lie-group Runge–Kutta, one rotation vector per body; O_1 by classical RK4).
ChainState chain_step(const NonlinearChain& chain, const ChainState& state, double h);

// One step of the Munthe-Kaas Lie-group form of Dormand–Prince 5(4) (dexp⁻¹ to fourth order in θ): the order-5
// state, the local error estimate (order 5 minus its embedded order 4) and the rates at the new state, which are
// the next step's first stage (first same as last). `rates` are the rates at `state` (from the previous step, or
// chain_rates).
struct ChainStepDP {
  ChainState next;
  ChainRates next_rates;
  double attitude_error = 0;             // largest |θ₅ − θ₄| over the bodies (rad)
  double rate_error = 0;                 // largest |ω₅ − ω₄|, |ζ₅ − ζ₄| (rad/s)
};
ChainStepDP chain_step_dp(const NonlinearChain& chain, const ChainState& state, const ChainRates& rates, double h);

}  // namespace rc::rom
