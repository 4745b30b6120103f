#include "nonlinear_run.hpp"

#include "chain_model.hpp"
#include "rigid_body.hpp"
#include "volume_tanks.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {

using Eigen::Vector3d;

int kept_modes(const NonlinearChain& chain) {
  int n = 0;
  for (const auto& b : chain.bodies) n += b.kept_modes;
  return n;
}

bool finite(const ChainState& s) {
  for (std::size_t k = 0; k < s.q.size(); ++k)
    if (!s.q[k].coeffs().allFinite() || !s.omega[k].allFinite()) return false;
  for (const auto& z : s.zeta)
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) return false;
  return s.r1.allFinite() && s.v1.allFinite();
}

// Kinetic energy + |gravitational| + elastic at the start: the size the energy drift is measured against.
double energy_scale(const NonlinearChain& c, const ChainState& s) {
  NonlinearChain no_potential = c;
  no_potential.gravity = 0;
  no_potential.field.setZero();
  no_potential.field_gradient.setZero();
  for (auto& j : no_potential.joints) j.stiffness = 0;
  const double kinetic = chain_energy(no_potential, s);
  return kinetic + std::abs(chain_energy(c, s) - kinetic);
}

}  // namespace

namespace {
// The body's external moments, force and aerodynamic moments as the scene gives them.
void set_external_loads(const BodySpec& b, ChainBody& body) {
  if (b.moment) {
    body.axial_moment = b.moment->axial;
    body.space_moment = Vector3d(b.moment->space.data());
    body.harmonic_moment = Vector3d(b.moment->harmonic.data());
    body.frequency = b.moment->frequency;
  }
  if (b.force) {
    body.space_force = Vector3d(b.force->space.data());
    body.harmonic_force = Vector3d(b.force->harmonic.data());
    body.force_frequency = b.force->frequency;
    body.force_at = b.force->at;
  }
  if (b.aero) {
    body.static_moment = b.aero->static_moment;
    body.pitch_damping = b.aero->pitch_damping;
    body.magnus = b.aero->magnus;
  }
}
}  // namespace

namespace {

// The bodies of a chain whose tanks are axisymmetric and on their axes: totals with the frozen fluid and the kept
// modes, as the linear model has them (chain_model.hpp).
std::vector<ChainBody> axisymmetric_tank_bodies(const Scene& scene) {
  const ChainModel model = build_model(scene, nullptr, false);
  const std::size_t n = scene.size();
  std::vector<ChainBody> out;
  for (std::size_t k = 0; k < n; ++k) {
    const BodySpec& b = scene.bodies[k];
    const BodyModel& t = model.bodies[k];
    // The cavity is axisymmetric: its frozen fluid adds the same to both transverse moments.
    ChainBody body;
    body.mass = t.m;
    body.A = t.A;
    body.B = b.B.value_or(b.A) + (t.A - b.A);
    body.C = b.C;  // the shell's: the liquid's axial part is a gyrostat's momentum (ChainBody::liquid_axial)
    if (!(b.C > 0) && t.C_f > 0)
      fail(scene, "body[" + std::to_string(k + 1) + "].C",
           "the shell has no axial inertia and its ideal liquid does not follow the shell's turns about the axis "
           "(docs/physics.md §3, \"Axial rotations\"), so the nonlinear chain cannot move its spin: give the shell's C > 0");
    body.liquid_axial = t.C_f;
    body.liquid_spin = b.spin;
    body.com = t.c;
    body.next_joint = k + 1 < n ? b.next_joint : 0.0;
    // The chain takes a viscous table's values for a positive spin (ChainFluidMode); the linear model's are for the
    // scene's spin, conjugated when it is negative.
    const auto as_positive_spin = [&](std::complex<double> E) { return b.spin < 0 ? std::conj(E) : E; };
    for (const FluidMode& m : model.modes)
      if (m.body == static_cast<int>(k)) {
        const double decay_table = m.decay > 0 ? m.decay / std::abs(b.spin) : 0.0;
        body.fluid.push_back({as_positive_spin(m.E_c()), {m.lambda_table, decay_table}});
      }
    // The static correction, the left-out modes' λ → 0 limit: in the body frame a mode of λ = 0 (frequency-independent
    // inertia in space, as in (26)'s M_eff; as E_total Ṗ alone in the body frame it would add a gyroscopic term).
    body.kept_modes = static_cast<int>(body.fluid.size());
    // (A viscous table's remainder may be purely imaginary: its residues cover the sum rule, and the correction then
    // only cancels their imaginary part; it is still a mode, or E_total Ṗ alone would add a gyroscopic term.)
    if (t.E_rem > 0 || t.E_rem_imag != 0) body.fluid.push_back({as_positive_spin({t.E_rem, t.E_rem_imag}), 0.0});
    body.fluid_E_total = as_positive_spin({t.E_kept + t.E_rem, t.E_kept_imag + t.E_rem_imag});
    if (t.ekman > 0) body.table_spin = b.spin;
    out.push_back(body);
  }
  return out;
}

}  // namespace

NonlinearChain nonlinear_chain(const Scene& scene) {
  NonlinearChain c;
  c.free_chain = scene.free_chain;
  c.gravity = scene.free_chain ? 0.0 : scene.gravity;  // uniform gravity does not turn a free chain (docs/scene-format.md)
  if (scene.field && !scene.free_chain) {  // nor does a uniform field
    c.field = Vector3d(scene.field->space.data());
    c.field_harmonic = Vector3d(scene.field->harmonic.data());
    c.field_frequency = scene.field->frequency;
  }
  if (scene.field)  // a gradient does turn a free chain (a satellite's gravity-gradient moment)
    c.field_gradient = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(scene.field->gradient.data());
  TableCache tables;
  c.bodies = needs_volume_tanks(scene, tables) ? volume_tank_bodies(scene, tables) : axisymmetric_tank_bodies(scene);
  for (std::size_t k = 0; k < scene.size(); ++k) set_external_loads(scene.bodies[k], c.bodies[k]);
  c.joints.push_back({0.0, scene.support_friction, scene.support_axial_friction});
  for (const JointSpec& j : scene.joints) c.joints.push_back({j.stiffness, j.friction, j.axial_friction});
  return c;
}

ChainState nonlinear_initial_state(const Scene& scene, const NonlinearChain& chain) {
  ChainState s;
  for (std::size_t k = 0; k < scene.size(); ++k) {
    const double beta = scene.tilt[k].real(), alpha = -scene.tilt[k].imag();
    // Every axis has Krylov angles β ∈ [−π/2, π/2], α ∈ [−π, π]; outside, the tilt names an attitude the angles
    // inside already name (and 1e300 rad names none a user means).
    constexpr double pi = 3.141592653589793;
    if (std::abs(beta) > pi / 2 || std::abs(alpha) > pi) {
      std::ostringstream os;
      os << "initial.tilt[" << k + 1 << "]: Krylov angles beta = Re u = " << beta << ", alpha = -Im u = " << alpha
         << " rad lie outside [-pi/2, pi/2] x [-pi, pi], where every axis has its angles; give them there";
      throw SceneError(scene.file.string() + ": " + os.str());
    }
    const double beta_dot = scene.rate[k].real(), alpha_dot = -scene.rate[k].imag();
    const Eigen::AngleAxisd first(-alpha, Vector3d::UnitX());
    // A body taken in its principal axes (volume_tanks.hpp) is the scene's body turned about its own axis.
    const Eigen::Quaterniond q = Eigen::Quaterniond(first) * Eigen::Quaterniond(Eigen::AngleAxisd(beta, Vector3d::UnitY())) *
                                 Eigen::Quaterniond(Eigen::AngleAxisd(chain.bodies[k].principal_turn, Vector3d::UnitZ()));
    const Vector3d n = q * Vector3d::UnitZ();
    const Vector3d transverse = -alpha_dot * Vector3d::UnitX() + beta_dot * (first * Vector3d::UnitY());
    // The spin is the axial component of Ω: add along n what makes Ω·n = ω_k0 + initial.axial_rate.
    const double change = scene.axial_rate.size() == scene.bodies.size() ? scene.axial_rate[k] : 0.0;
    const Vector3d Omega = transverse + (scene.bodies[k].spin + change - transverse.dot(n)) * n;
    s.q.push_back(q);
    s.omega.push_back(q.conjugate() * Omega);
  }
  // The fluid: the scene's z_kl(0) for the kept modes (ζ = z at t = 0). The static correction's mode starts where it
  // stays, ζ = −i P (P = p − i q, the body's transverse angular velocity in its frame): then its moment is
  // E_rem (Ṗ − i r P), the frequency-independent inertia E_rem of (26)'s M_eff (z = −u̇, w = 0 in (26)'s terms).
  const Eigen::VectorXcd z0 = initial_fluid(scene, kept_modes(chain));
  for (int k = 0, l = 0; k < chain.size(); ++k) {
    const std::complex<double> P(s.omega[k].x(), -s.omega[k].y());
    for (std::size_t j = 0; j < chain.bodies[k].fluid.size(); ++j)
      s.zeta.push_back(static_cast<int>(j) < chain.bodies[k].kept_modes ? z0[l++] : std::complex<double>(0, -1) * P);
    s.zeta.resize(s.zeta.size() + chain.bodies[k].volume.size(), 0.0);  // tanks without axial symmetry: at rest
  }
  if (chain.free_chain) {
    // The whole chain's centre of mass at rest (as the linear free chain takes it, docs/free-chain.md): O_1 moves
    // against the bodies' swing.
    Vector3d momentum = Vector3d::Zero(), joint_velocity = Vector3d::Zero();
    double mass = 0;
    for (int k = 0; k < chain.size(); ++k) {
      const ChainBody& b = chain.bodies[k];
      const Vector3d n = s.q[k] * Vector3d::UnitZ(), Omega = s.q[k] * s.omega[k];
      momentum += b.mass * (joint_velocity + Omega.cross(b.com * n));
      mass += b.mass;
      joint_velocity += Omega.cross(b.next_joint * n);
    }
    if (mass > 0) s.v1 = -momentum / mass;
  }
  return s;
}

Eigen::VectorXcd nonlinear_tilts(const ChainState& state) {
  Eigen::VectorXcd u(state.q.size());
  for (std::size_t k = 0; k < state.q.size(); ++k) {
    const Vector3d n = state.q[k] * Vector3d::UnitZ();
    u[k] = {n.x(), -n.y()};
  }
  return u;
}

namespace {

// Writes each output sample of a nonlinear run: tilts, energy and its drift, angular momentum and its drift,
// attitudes, spins, the viscous tanks' spin change and the fluid's amplitudes.
class NonlinearRecorder {
 public:
  NonlinearRecorder(const NonlinearChain& chain, const ChainState& initial, long samples, NonlinearHistory& out)
      : chain_(chain), out_(out), h_(out.base), n_(chain.size()),
        H0_(chain_energy(chain, initial)), H_scale_(energy_scale(chain, initial)),
        L0_(chain_angular_momentum(chain, initial)),
        damped_(std::any_of(chain.joints.begin(), chain.joints.end(),
                            [](const ChainJoint& j) { return j.friction > 0 || j.axial_friction > 0; })),
        loaded_(nonconservative(chain) && chain.fluid_modes() == 0),
        previous_H_(H0_) {
    h_.method_used = "nonlinear-rkmk-dp54";
    h_.u.resize(samples, n_);
    h_.z.resize(samples, 0);
  }

  void operator()(long j, double t, const ChainState& s) {
    h_.t.push_back(t);
    h_.u.row(j) = nonlinear_tilts(s).transpose();
    const double H = chain_energy(chain_, s);
    h_.H.push_back(H);
    h_.H_scale.push_back(H_scale_);
    h_.max_energy_drift =
        std::max(h_.max_energy_drift, damped_ ? (H - previous_H_) / H_scale_ : std::abs(H - H0_) / H_scale_);
    previous_H_ = H;
    if (loaded_) balance(t, H, s);
    const Vector3d L = chain_angular_momentum(chain_, s);
    // Conserved: the whole vector for the free chain, its vertical component about O_1 for the fixed one.
    const double change = chain_.free_chain ? (L - L0_).norm() : std::abs(L.z() - L0_.z());
    if (L0_.norm() > 0) out_.max_momentum_drift = std::max(out_.max_momentum_drift, change / L0_.norm());
    for (int k = 0; k < n_; ++k) {
      const auto& q = s.q[k];
      out_.quaternions.insert(out_.quaternions.end(), {q.w(), q.x(), q.y(), q.z()});
      out_.spins.push_back((q * s.omega[k]).dot(q * Vector3d::UnitZ()));
    }
    for (int k = 0; k < n_; ++k)
      if (chain_.bodies[k].table_spin != 0)
        out_.viscous_spin_change = std::max(out_.viscous_spin_change,
                                            std::abs(s.omega[k].z() / chain_.bodies[k].table_spin - 1));
    out_.momentum.insert(out_.momentum.end(), {L.x(), L.y(), L.z()});
    out_.zeta.insert(out_.zeta.end(), s.zeta.begin(), s.zeta.end());
  }

 private:
  const NonlinearChain& chain_;
  NonlinearHistory& out_;
  History& h_;
  const int n_;
  const double H0_, H_scale_;
  const Vector3d L0_;
  const bool damped_, loaded_;
  double previous_H_;
  double previous_t_ = 0, previous_P_ = 0, work_ = 0;

  // Batyr's energy balance (11): H(t) − H(0) = W(t), the work of the loads the energy does not hold
  // (nonconservative_power), by the trapezoid rule on the output samples; the largest gap relative to H's scale.
  void balance(double t, double H, const ChainState& s) {
    const double P = nonconservative_power(chain_, s);
    if (h_.t.size() > 1) work_ += 0.5 * (P + previous_P_) * (t - previous_t_);
    previous_t_ = t;
    previous_P_ = P;
    const double gap = std::abs(H - H0_ - work_) / H_scale_;
    h_.work_balance = std::isnan(h_.work_balance) ? gap : std::max(h_.work_balance, gap);
  }
};

// Advances s from t to t_out by Dormand-Prince steps on the chain's Lie group (chain_step_dp), each accepted when its
// error is within run.tolerance; `step` is the next trial step, carried from call to call.
void advance_to(const NonlinearChain& chain, ChainState& s, ChainRates& rates, double& t, double t_out, double& step,
                const RunSpec& run, NonlinearHistory& out) {
  // The steps' sum can fall short of t_out by a rounding (0.05 reached as 0.049999999999999996): what is left below
  // 1e-13 of the time is no step, else the run would stop there for a step too small (found on a free spacecraft).
  const double tiny = 1e-13 * std::max(1.0, t_out);
  const auto number = [](double x) {
    std::ostringstream os;
    os << x;
    return os.str();
  };
  while (t_out - t > tiny) {
    const double hh = std::min(step, t_out - t);
    if (hh < tiny)
      throw std::runtime_error("nonlinear run: the step fell below 1e-13 s at t = " + number(t) +
                               ": run.tolerance " + number(run.tolerance) + " cannot be met in double "
                               "precision; raise it");
    const ChainStepDP dp = chain_step_dp(chain, s, rates, hh);
    double rate_scale = 1;
    for (const auto& w : dp.next.omega) rate_scale = std::max(rate_scale, w.norm());
    const double err = std::max(dp.attitude_error, dp.rate_error / rate_scale);
    if (++out.base.integrator_steps > kMaxIntegratorSteps)
      throw std::runtime_error("nonlinear run: more than " + std::to_string(long(kMaxIntegratorSteps)) +
                               " steps for run.tolerance " + number(run.tolerance) +
                               "; raise the tolerance or shorten t_end");
    if (!std::isfinite(err)) throw std::runtime_error("nonlinear run: the state is not finite at t = " + std::to_string(t));
    const double factor = err > 0 ? 0.9 * std::pow(run.tolerance / err, 0.2) : 4.0;
    if (err <= run.tolerance) {
      s = dp.next;
      rates = dp.next_rates;  // first same as last
      t += hh;
      if (hh == step) step *= std::clamp(factor, 0.2, 5.0);  // a step cut short by the output grid says nothing
    } else {
      ++out.rejected_steps;
      step = hh * std::clamp(factor, 0.1, 0.9);
    }
  }
}

}  // namespace

NonlinearHistory integrate_nonlinear(const NonlinearChain& chain, const ChainState& initial, const RunSpec& run) {
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const long samples = std::lround(run.t_end / run.output_step) + 1;
  NonlinearHistory out;
  NonlinearRecorder record(chain, initial, samples, out);
  out.fluid_modes = chain.fluid_modes();
  out.integrals_valid = out.fluid_modes == 0;
  out.momentum_valid = std::all_of(chain.bodies.begin(), chain.bodies.end(), [](const ChainBody& b) { return b.fluid.empty(); });
  out.viscous_tanks = std::any_of(chain.bodies.begin(), chain.bodies.end(), [](const ChainBody& b) { return b.table_spin != 0; });

  ChainState s = initial;
  record(0, 0.0, s);
  double rate = 1;
  for (const auto& w : s.omega) rate = std::max(rate, w.norm());
  double step = std::min(run.output_step, 0.05 / rate);
  double t = 0;
  ChainRates rates = chain_rates(chain, s);
  for (long j = 1; j < samples; ++j) {
    const double t_out = std::min(run.t_end, j * run.output_step);
    advance_to(chain, s, rates, t, t_out, step, run, out);
    t = t_out;
    s.t = t_out;  // no rounding drift in the time the moments see
    if (!finite(s)) throw std::runtime_error("nonlinear run: the state is not finite at t = " + std::to_string(t));
    record(j, t, s);
  }
  out.base.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  out.base.cpu_seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace rc::rom
