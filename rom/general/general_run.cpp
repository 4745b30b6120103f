#include "general_run.hpp"

#include "balancing.hpp"
#include "floquet.hpp"
#include "periodic_system.hpp"
#include "general_system.hpp"

#include "matrix_exponential.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

}  // namespace

// y(0) from the scene's u_k(0), u̇_k(0): in F, v = e^{iω0t}u gives v(0) = u(0), v̇(0) = u̇(0) + iω0 u(0), and
// q = (Re v, −Im v); the spins at ω0; the fluid's modes at `initial.fluid`, each its z(0) in its body's frame
// (general_tank.hpp: the flow z V e^{iλt}; F and the bodies' frames coincide at t = 0), at rest without it.
void require_unforced(const Scene& scene) {
  const std::string why = " drives the chain, which a linear run of the chain without axial symmetry does not take "
                          "yet: run it with [run] model = \"nonlinear\" (its roots, maps and responses do not depend on it)";
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const std::string key = "body[" + std::to_string(k + 1) + "]";
    if (scene.bodies[k].moment) throw SceneError(scene.file.string() + ": " + key + ".moment: an external moment" + why);
    if (scene.bodies[k].force) throw SceneError(scene.file.string() + ": " + key + ".force: an external force" + why);
  }
  if (scene.field) {
    const FieldSpec& f = *scene.field;
    if (f.space[0] != 0 || f.space[1] != 0 || f.harmonic[0] != 0 || f.harmonic[1] != 0)
      throw SceneError(scene.file.string() + ": field: a transverse field" + why);
  }
}

Eigen::VectorXd general_initial_state(const GeneralChain& g, const GeneralSystem& sys, const Scene& scene) {
  require_unforced(scene);
  const Eigen::VectorXcd z0 = initial_fluid(scene, g.n_modes());  // one pair per kept mode, body by body
  for (const double change : scene.axial_rate)
    if (change != 0)
      throw SceneError(scene.file.string() + ": initial.axial_rate: a linear run of the chain without axial symmetry "
                       "starts with its spins at omega_k0; the axisymmetric chain (26) and the nonlinear model "
                       "([run] model = \"nonlinear\") take a change of spin");
  Eigen::VectorXd y = Eigen::VectorXd::Zero(sys.dim());
  const int nq = 2 * g.n;
  for (int k = 0; k < g.n; ++k) {
    const cd u = scene.tilt[k], v_dot = scene.rate[k] + cd(0, g.spin) * u;
    y[2 * k] = sys.s * u.real();
    y[2 * k + 1] = -sys.s * u.imag();
    y[nq + 2 * k] = v_dot.real();
    y[nq + 2 * k + 1] = -v_dot.imag();
  }
  for (int l = 0; l < g.n_modes(); ++l) {
    y[nq + g.dim_q() + 2 * l] = z0[l].real();
    y[nq + g.dim_q() + 2 * l + 1] = z0[l].imag();
  }
  return y;
}

namespace {

// One body, no gravity, field, aerodynamic moment or friction: the angular momentum in space is an integral
// (general_run.hpp).
bool has_momentum_integral(const GeneralChain& g, const Scene& scene) {
  return g.n == 1 && !g.recoil && (scene.free_chain || scene.gravity == 0) && !scene.field && !scene.bodies[0].aero &&
         !g.dissipative && scene.support_friction == 0;
}

// δL in space and the size of its largest term, from the state y at time t (general_run.hpp; docs/rom.md).
Eigen::Vector3d angular_momentum(const GeneralChain& g, const GeneralSystem& sys, const Eigen::VectorXd& y, double t,
                                 double& size) {
  const double w = g.spin;
  const Eigen::Matrix2d Mq = g.M.topLeftCorner<2, 2>(), J = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();
  const Eigen::Matrix2d I_tt = Mq.trace() * Eigen::Matrix2d::Identity() - Mq;  // the θ-frame tensor: Ā I + Δ
  const Eigen::Vector2d q = y.head<2>() / sys.s, q_dot = y.segment<2>(2);
  Eigen::Vector3d dw;
  dw.head<2>() = J * q_dot - w * q;
  dw.z() = g.axial ? y[4] : 0.0;
  Eigen::Vector3d h = -g.geostrophic[0] * dw;
  const int z0 = 2 + g.dim_q();
  for (int l = 0; l < g.n_modes(); ++l) h += 2 * (cd(y[z0 + 2 * l], y[z0 + 2 * l + 1]) * g.modes[l].c).real();
  Eigen::Vector3d L;
  L.head<2>() = g.axial_inertia[0] * w * q + I_tt * dw.head<2>();
  L.z() = g.axial_inertia[0] * dw.z();
  size = std::max({L.head<2>().norm(), (I_tt * dw.head<2>()).norm(), h.norm(), std::abs(L.z())});
  L += h;
  const Eigen::Rotation2Dd turn(w * t);  // F turns at ω0 about the vertical
  L.head<2>() = turn * L.head<2>().eval();
  return L;
}

void record(const GeneralChain& g, const GeneralSystem& sys, const Eigen::VectorXd& y, double t, long j,
            GeneralHistory& h) {
  const int nq = 2 * g.n, d = g.dim_q();
  for (int k = 0; k < g.n; ++k)
    h.u(j, k) = std::exp(cd(0, -g.spin * t)) * cd(y[2 * k], -y[2 * k + 1]) / sys.s;
  for (int l = 0; l < g.n_modes(); ++l) h.z(j, l) = cd(y[nq + d + 2 * l], y[nq + d + 2 * l + 1]);
  if (g.axial)
    for (int k = 0; k < g.n; ++k) h.spin(j, k) = g.spins[k] + y[nq + 2 * g.n + k];
}

// The first-order form at t = 0; a periodic chain's only for its scale s and the initial state.
GeneralSystem initial_system(const GeneralChain& g) {
  if (!g.periodic()) return build_general_system(g);
  GeneralSystem sys = build_general_system(turned_chain(g, 0));  // floquet.hpp's scale
  sys.B = periodic_matrix(g, 0, sys.s);
  return sys;
}

// y at the output times: exp(B h) (B balanced first) over each output step h when the coefficients are constant; a
// periodic chain's Magnus steps (floquet.hpp), as many a period as its roots settled with.
class OutputSteps {
 public:
  OutputSteps(const GeneralChain& g, const GeneralSystem& sys, double h, const Eigen::VectorXd& y0, int per_period)
      : y_(y0) {
    if (g.periodic()) {
      periodic_.emplace(g, sys.s, per_period > 0 ? per_period : floquet_steps(g).per_period, y0);
      return;
    }
    Eigen::MatrixXd B = sys.B;
    const Eigen::VectorXd S = balance_in_place(B);  // B = S B' S⁻¹: exp(B h) = S exp(B' h) S⁻¹
    constant_ = S.asDiagonal() * rc::matrix_exponential(Eigen::MatrixXd(B * h)) * S.cwiseInverse().asDiagonal();
  }
  // y at the next output time t.
  const Eigen::VectorXd& next(double t) {
    y_ = periodic_ ? periodic_->at(t) : (constant_ * y_).eval();
    return y_;
  }

 private:
  std::optional<PeriodicPropagator> periodic_;
  Eigen::MatrixXd constant_;
  Eigen::VectorXd y_;
};

}  // namespace

GeneralHistory propagate_general(const GeneralChain& g, const Scene& scene, int steps_per_period) {
  if (scene.run.method != "exact")
    throw std::runtime_error(scene.file.string() + ": run.method: the chain without axial symmetry is propagated "
                             "exactly only (method = \"exact\")");
  const auto t0 = std::chrono::steady_clock::now();
  const GeneralSystem sys = initial_system(g);
  const long steps = std::lround(scene.run.t_end / scene.run.output_step) + 1;
  const double h_step = scene.run.output_step;
  GeneralHistory h;
  h.u.resize(steps, g.n);
  h.z.resize(steps, g.n_modes());
  if (g.axial) h.spin.resize(steps, g.n);
  Eigen::VectorXd y = general_initial_state(g, sys, scene);
  OutputSteps steps_to(g, sys, h_step, y, steps_per_period);
  const bool momentum = has_momentum_integral(g, scene);
  double size0 = 0, largest = 0, drift = 0;
  const Eigen::Vector3d L0 = momentum ? angular_momentum(g, sys, y, 0, size0) : Eigen::Vector3d::Zero();
  for (long j = 0; j < steps; ++j) {
    const double t = static_cast<double>(j) * h_step;
    if (j > 0) y = steps_to.next(t);
    if (!y.allFinite())
      throw std::runtime_error("the trajectory is not finite at t = " + std::to_string(t) + " s: the chain's magnitudes "
                               "leave double precision; nothing written");
    h.t.push_back(t);
    record(g, sys, y, t, j, h);
    if (!momentum) continue;
    double size = 0;
    drift = std::max(drift, (angular_momentum(g, sys, y, t, size) - L0).norm());
    largest = std::max(largest, size);
  }
  if (momentum) h.momentum_drift = largest > 0 ? drift / largest : 0.0;
  h.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

}  // namespace rc::rom
