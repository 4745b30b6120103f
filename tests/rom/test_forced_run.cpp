// The linear chain (26) under external moments (rom/linear/forced_solution.hpp): against the nonlinear chain at small
// amplitude (the difference falling as the amplitude squared), against the frequency response's steady oscillation,
// the three integrators against each other, and what it refuses.
#include "chain_model.hpp"
#include "first_order_system.hpp"
#include "forced_solution.hpp"
#include "frequency_response.hpp"
#include "nonlinear_run.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

using namespace rc::rom;
using cd = std::complex<double>;

namespace {

// A gyroscopic pendulum (centre of mass below O_1) with friction at the support, a constant and a harmonic moment in
// space, released with a small tilt; every value of tilt and moment times `scale`.
std::string pendulum(double scale, double t_end, const std::string& method = "exact", const std::string& model = "") {
  const auto num = [](double x) { return std::to_string(x); };
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\n"
         "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nspin = 30.0\n"
         "[body.moment]\nspace = [" + num(0.004 * scale) + ", " + num(-0.003 * scale) + ", 0.0]\nharmonic = [" +
         num(0.02 * scale) + ", " + num(0.01 * scale) + ", 0.0]\nfrequency = 1.5\n"
         "[initial]\ntilt = [[" + num(0.002 * scale) + ", " + num(-0.001 * scale) + "]]\n"
         "[run]\nt_end = " + num(t_end) + "\noutput_step = 0.01\ntolerance = 1e-11\n" +
         (model.empty() ? "method = \"" + method + "\"\n" : model);
}

}  // namespace

// At small amplitude the forced linear run is the nonlinear chain (a separate model: rigid bodies at any angle, the
// moments applied in space), the difference relative to the amplitude falling as the amplitude squared.
TEST(ForcedRun, IsTheNonlinearChainAtSmallAmplitude) {
  std::vector<double> rel;
  for (double scale : {1.0, 0.5}) {
    const Scene s = parse_scene_text(pendulum(scale, 5.0), ".", "forced");
    const History linear = propagate(build_model(s), s);
    const Scene sn = parse_scene_text(pendulum(scale, 5.0, "", "model = \"nonlinear\"\n"), ".", "forced-nl");
    const NonlinearChain chain = nonlinear_chain(sn);
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(sn, chain), sn.run);
    ASSERT_EQ(linear.t.size(), nl.base.t.size());
    double diff = 0;
    for (Eigen::Index j = 0; j < linear.u.rows(); ++j)
      diff = std::max(diff, std::abs(linear.u(j, 0) - nl.base.u(j, 0)));
    rel.push_back(diff / linear.u.cwiseAbs().maxCoeff());
    std::printf("  scale %.1f: largest tilt %.3e rad over 5 s, linear forced run against the nonlinear chain %.2e of it\n",
                scale, linear.u.cwiseAbs().maxCoeff(), rel.back());
    EXPECT_TRUE(linear.forced);
  }
  std::printf("  halving tilt and moments: the difference falls by %.2f (amplitude squared: 4)\n", rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.5);
}

namespace {
// Two gyroscopic pendulums joined elastically (centres of mass below their joints), friction at the support; on the
// second a force at 0.25 m along its axis — a constant transverse part and an axial one, and a harmonic transverse part;
// tilts and transverse forces times `scale`.
std::string forced_pendulums(double scale, const std::string& model = "method = \"exact\"\n") {
  const auto num = [](double x) { return std::to_string(x); };
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\n"
         "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nnext_joint = -0.3\nspin = 30.0\n"
         "[[body]]\nmass = 1.0\nA = 0.02\nC = 0.01\ncom = -0.12\nspin = 20.0\n"
         "[body.force]\nat = -0.25\nspace = [" + num(0.05 * scale) + ", " + num(-0.03 * scale) + ", -4.0]\nharmonic = [" +
         num(0.2 * scale) + ", " + num(0.1 * scale) + ", 0.0]\nfrequency = 1.2\n"
         "[[joint]]\nstiffness = 3.0\nfriction = 0.02\n"
         "[initial]\ntilt = [[" + num(0.002 * scale) + ", 0.0], [" + num(-0.001 * scale) + ", 0.001]]\n"
         "[run]\nt_end = 5.0\noutput_step = 0.01\ntolerance = 1e-11\n" + model;
}
}  // namespace

// Batyr's energy balance (11) with the external moments' power: a forced run's H changes by the work of its moments,
// forces and field less the friction's, ∫ Re(F̄ᵀu̇) − u̇ᴴDu̇ dt (History::work_balance, the trapezoid rule on the
// output samples): its error falls as the output step squared, and a wrong power (the moments left out) fails it.
TEST(ForcedRun, EnergyChangesByTheWorkOfTheMoments) {
  std::vector<double> balance;
  for (const double step : {0.01, 0.005}) {
    std::string text = forced_pendulums(1.0);
    text.replace(text.find("output_step = 0.01"), 18, "output_step = " + std::to_string(step));
    const Scene s = parse_scene_text(text, ".", "work");
    const History h = propagate(build_model(s), s);
    balance.push_back(h.work_balance);
    std::printf("  output step %.3f s: max |H(t) - H(0) - W(t)| = %.2e of H's largest scale (H from %.4e to %.4e)\n", step,
                h.work_balance, h.H.front(), h.H.back());
  }
  std::printf("  halving the step: the balance's error falls by %.2f (trapezoid rule: 4)\n", balance[0] / balance[1]);
  EXPECT_LT(balance[1], 1e-3);
  EXPECT_GT(balance[0] / balance[1], 3.5);
}

namespace {
// The linear run against the nonlinear chain for the scene text(scale, model lines) at scales 1 and 0.5: the largest
// difference of the tilts relative to the largest tilt, per scale.
std::vector<double> linear_against_nonlinear(std::string (*text)(double, const std::string&)) {
  std::vector<double> rel;
  for (double scale : {1.0, 0.5}) {
    const Scene s = parse_scene_text(text(scale, "method = \"exact\"\n"), ".", "linear");
    const History linear = propagate(build_model(s), s);
    const Scene sn = parse_scene_text(text(scale, "model = \"nonlinear\"\n"), ".", "nonlinear");
    const NonlinearChain chain = nonlinear_chain(sn);
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(sn, chain), sn.run);
    EXPECT_EQ(linear.t.size(), nl.base.t.size());
    if (linear.t.size() != nl.base.t.size()) return {1.0, 1.0};
    rel.push_back((linear.u - nl.base.u).cwiseAbs().maxCoeff() / linear.u.cwiseAbs().maxCoeff());
    std::printf("  scale %.1f: largest tilt %.3e rad over 5 s, linear against nonlinear %.2e of it\n", scale,
                linear.u.cwiseAbs().maxCoeff(), rel.back());
  }
  return rel;
}
}  // namespace

// External forces (Batyr's F_k): the linear chain takes a force's transverse part as the moments ℓ e_z × F on the body
// (ℓ = at) and on every body below it (ℓ = s_j, through its joint), its constant axial part as the stiffness of its
// potential; the nonlinear chain applies the force at its point in space. (1) The static tilt of one pendulum under a
// constant force is the closed form u = at (F_x − i F_y)/(F_z at − a g); (2) two pendulums, forced at the second, are
// the nonlinear chain at small amplitude, the difference falling as the amplitude squared.
TEST(ForcedRun, ForcesAreTheNonlinearChainsAtSmallAmplitude) {
  const std::string one = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\n"
                          "com = -0.1\nspin = 30.0\n[body.force]\nat = -0.25\nspace = [0.05, -0.03, -4.0]\n";
  const Scene s1 = parse_scene_text(one, ".", "force-static");
  const ChainModel m1 = build_model(s1);
  const FirstOrderSystem f1 = build_first_order(m1);
  const cd u_static = forced_solution(m1, f1, s1).constant[0] / f1.s;
  const double at = -0.25, Fz = -4.0, a = 2.0 * -0.1, g = 9.81;
  const cd u_closed = at * cd(0.05, 0.03) / (Fz * at - a * g);
  std::printf("  static tilt under the force: %.12e%+.12ei, closed form %.12e%+.12ei (relative %.1e)\n", u_static.real(),
              u_static.imag(), u_closed.real(), u_closed.imag(), std::abs(u_static - u_closed) / std::abs(u_closed));
  EXPECT_LT(std::abs(u_static - u_closed) / std::abs(u_closed), 1e-12);
  const std::vector<double> rel = linear_against_nonlinear(forced_pendulums);
  std::printf("  halving tilts and transverse forces: the difference falls by %.2f (amplitude squared: 4)\n",
              rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.5);
}

namespace {
// forced_pendulums' chain (no force) with the field `field` (its [field] keys); tilts times `scale`.
std::string pendulums_with_field(const std::string& field, double scale, const std::string& model) {
  const auto num = [](double x) { return std::to_string(x); };
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\n[field]\n" + field +
         "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nnext_joint = -0.3\nspin = 30.0\n"
         "[[body]]\nmass = 1.0\nA = 0.02\nC = 0.01\ncom = -0.12\nspin = 20.0\n"
         "[[joint]]\nstiffness = 3.0\nfriction = 0.02\n"
         "[initial]\ntilt = [[" + num(0.002 * scale) + ", 0.0], [" + num(-0.001 * scale) + ", 0.001]]\n"
         "[run]\nt_end = 5.0\noutput_step = 0.01\ntolerance = 1e-11\n" + model;
}

// In a uniform field: a constant part (transverse and axial) and a harmonic transverse one; tilts and transverse parts
// times `scale`.
std::string pendulums_in_field(double scale, const std::string& model = "method = \"exact\"\n") {
  const auto num = [](double x) { return std::to_string(x); };
  return pendulums_with_field("space = [" + num(0.03 * scale) + ", " + num(-0.02 * scale) + ", -2.0]\nharmonic = [" +
                                  num(0.05 * scale) + ", " + num(0.04 * scale) + ", 0.0]\nfrequency = 0.8\n",
                              scale, model);
}
}  // namespace

// A uniform field f (Batyr's body force field, uniform in space; the scene's [field]) is tilted gravity: the linear
// chain's static tilt under its constant part is every body's −(f_x − i f_y)/(g − f_z) (the chain hangs along the
// effective gravity, its joints unstressed), and with a harmonic part it is the nonlinear chain at small amplitude,
// the difference falling as the amplitude squared.
TEST(ForcedRun, UniformFieldIsTiltedGravity) {
  const Scene s0 = parse_scene_text(pendulums_in_field(1.0), ".", "field-static");
  const ChainModel m0 = build_model(s0);
  const FirstOrderSystem f0 = build_first_order(m0);
  const Eigen::VectorXcd u_static = forced_solution(m0, f0, s0).constant.head(2) / f0.s;
  const cd u_closed = -cd(0.03, 0.02) / (9.81 - -2.0);
  const double static_error = (u_static.array() - u_closed).abs().maxCoeff() / std::abs(u_closed);
  std::printf("  static tilts %.10f%+.10fi, %.10f%+.10fi; along the effective gravity %.10f%+.10fi (relative %.1e)\n",
              u_static[0].real(), u_static[0].imag(), u_static[1].real(), u_static[1].imag(), u_closed.real(),
              u_closed.imag(), static_error);
  EXPECT_LT(static_error, 1e-12);
  const std::vector<double> rel = linear_against_nonlinear(pendulums_in_field);
  std::printf("  halving tilts and transverse field: the difference falls by %.2f (amplitude squared: 4)\n",
              rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.5);
}

// A uniform force field of Batyr (the scene's [field]): a support vibrating vertically, y = a sin Ωt, is the axial field
// −ÿ = a Ω² sin Ωt on every mass. The nonlinear chain holds an inverted pendulum up when (aΩ)² > 2 g A/(m ℓ) (Kapitza
// 1951, "Dynamic stability of a pendulum when its point of suspension vibrates"; A about the pivot, ℓ = com above it)
// and lets it fall below: at 50 Hz, 30 % above and below the threshold's acceleration amplitude.
TEST(ForcedRun, VibratingSupportHoldsTheInvertedPendulumAsKapitzaSays) {
  const double m = 1.0, l = 0.1, A = 0.01, g = 9.81, f = 50.0, Omega = 2 * std::numbers::pi * f;
  const double threshold = Omega * std::sqrt(2 * g * A / (m * l));  // acceleration amplitude a Ω² at (aΩ)² = 2gA/(mℓ)
  double held = 0, fallen = 0;
  for (const double factor : {1.3, 0.7}) {
    const std::string text = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[field]\nharmonic = [0.0, 0.0, " +
                             std::to_string(factor * threshold) + "]\nfrequency = 50.0\n[[body]]\nmass = 1.0\n"
                             "A = 0.01\nC = 0.001\ncom = 0.1\n[initial]\ntilt = [[0.05, 0.0]]\n[run]\nt_end = 3.0\n"
                             "output_step = 0.001\ntolerance = 1e-8\nmodel = \"nonlinear\"\n";
    const Scene s = parse_scene_text(text, ".", "kapitza");
    const NonlinearChain chain = nonlinear_chain(s);
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(s, chain), s.run);
    const double largest = nl.base.u.cwiseAbs().maxCoeff();
    std::printf("  a Omega^2 = %.1f m/s^2 (%.1f x Kapitza's threshold %.1f): largest tilt over 3 s %.3f rad from 0.05\n",
                factor * threshold, factor, threshold, largest);
    (factor > 1 ? held : fallen) = largest;
    if (factor < 1) continue;
    // Kapitza's averaged motion: θ = θ_s(1 − ε sin Ωt), ε = mℓa/A (a = aΩ²/Ω²), θ_s in the effective potential of
    // frequency ω_s² = (mℓaΩ)²/(2A²) − mgℓ/A. Started at rest, the slow motion starts with the rate εΩθ0 that cancels
    // the fast one's: its amplitude is θ0 √(1 + (εΩ/ω_s)²), the tilt's largest that times (1 + ε).
    const double a = factor * threshold / (Omega * Omega), eps = m * l * a / A;
    const double ws = std::sqrt(std::pow(m * l * a * Omega, 2) / (2 * A * A) - m * g * l / A);
    const double predicted = 0.05 * std::sqrt(1 + std::pow(eps * Omega / ws, 2)) * (1 + eps);
    std::printf("    Kapitza's averaged motion: largest tilt %.3f rad (slow frequency %.2f rad/s, eps %.4f); relative %.1e\n",
                predicted, ws, eps, std::abs(largest - predicted) / predicted);
    EXPECT_LT(std::abs(largest - predicted) / predicted, 0.1);
  }
  EXPECT_GT(fallen, 0.5);
}

// Long after its start has decayed the run is the steady response: the static K⁻¹F_c (Z(0) = K) plus the harmonic
// (h_y + i h_x)/(2i)[H(Ω)e^{iΩt} − H(−Ω)e^{−iΩt}] of frequency_response.hpp — the closed-form particular solution and
// Z(σ) checked against each other. The Gauss and Dormand–Prince integrators give the same forced run.
TEST(ForcedRun, BecomesTheResponsesSteadyOscillation) {
  const Scene s = parse_scene_text(pendulum(1.0, 300.0), ".", "forced");
  const ChainModel m = build_model(s);
  const History h = propagate(m, s);
  const double Omega = 3 * std::numbers::pi;
  const cd Hp = frequency_response(m, 0, Omega, 2 * Omega, 2).tilt(0, 0);
  const cd Hm = frequency_response(m, 0, -Omega, Omega, 2).tilt(0, 0);
  const cd H0 = frequency_response(m, 0, 0, 1, 2).tilt(0, 0);
  const cd Fc(-0.003, 0.004), Fh(0.01, 0.02);
  double worst = 0, amplitude = 0;
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    const double t = h.t[j];
    if (t < 298) continue;
    const cd steady = H0 * Fc + Fh / cd(0, 2) * (Hp * std::exp(cd(0, Omega * t)) - Hm * std::exp(cd(0, -Omega * t)));
    worst = std::max(worst, std::abs(h.u(static_cast<Eigen::Index>(j), 0) - steady));
    amplitude = std::max(amplitude, std::abs(steady));
  }
  std::printf("  after 298 s (slowest decay %.3f 1/s): the run against the steady response %.1e of its %.3e rad\n",
              -compute_verdict(m).growth, worst / amplitude, amplitude);
  EXPECT_LT(worst / amplitude, 1e-9);
  const Scene e = parse_scene_text(pendulum(1.0, 5.0), ".", "forced");
  const History exact = propagate(build_model(e), e);
  for (const char* method : {"gauss", "rk45"}) {
    const Scene g = parse_scene_text(pendulum(1.0, 5.0, method), ".", "forced");
    const History other = propagate(build_model(g), g);
    const double d = (other.u - exact.u).cwiseAbs().maxCoeff() / exact.u.cwiseAbs().maxCoeff();
    std::printf("  %s against exact over 5 s: %.1e\n", method, d);
    EXPECT_LT(d, 1e-7);
  }
}

TEST(ForcedRun, RefusesWhatHasNoClosedForm) {
  // An axial moment is no longer refused: it drives the spins' own block (axial_rotation.hpp), spun up at M/C.
  std::string axial = pendulum(1.0, 1.0);
  axial.replace(axial.find("[body.moment]\n"), 14, "[body.moment]\naxial = 0.1\n");
  const Scene a = parse_scene_text(axial, ".", "axial");
  const History spun = propagate(build_model(a), a);
  ASSERT_EQ(spun.spin.rows(), static_cast<Eigen::Index>(spun.t.size()));
  EXPECT_NEAR(spun.spin(spun.spin.rows() - 1, 0), 30.0 + 0.1 / 0.03 * spun.t.back(), 1e-12);
  // No gravity and no spring: a constant moment tips the body without bound (a zero root).
  std::string drift = pendulum(1.0, 1.0);
  drift.replace(drift.find("gravity = 9.81"), 14, "gravity = 0.0");
  const Scene d = parse_scene_text(drift, ".", "drift");
  try {
    propagate(build_model(d), d);
    ADD_FAILURE() << "a constant moment on a chain with a zero root was propagated";
  } catch (const std::runtime_error& err) {
    std::printf("  refused: %s\n", err.what());
    EXPECT_NE(std::string(err.what()).find("without bound"), std::string::npos);
  }
}

namespace {
// max |H(t) − H(0) − W(t)| / scale of a nonlinear run of `text` (output_step = 0.01 in it) at output steps 0.01, 0.005.
std::vector<double> nonlinear_balance(const std::string& text) {
  std::vector<double> balance;
  for (const double step : {0.01, 0.005}) {
    std::string t = text;
    t.replace(t.find("output_step = 0.01"), 18, "output_step = " + std::to_string(step));
    const Scene s = parse_scene_text(t, ".", "nonlinear-work");
    const NonlinearChain chain = nonlinear_chain(s);
    EXPECT_TRUE(nonconservative(chain));
    const NonlinearHistory h = integrate_nonlinear(chain, nonlinear_initial_state(s, chain), s.run);
    balance.push_back(h.base.work_balance);
    std::printf("  output step %.3f s: max |H(t) - H(0) - W(t)| = %.2e of H's scale (H from %.4e to %.4e, largest "
                "tilt %.3f)\n", step, h.base.work_balance, h.base.H.front(), h.base.H.back(),
                h.base.u.cwiseAbs().maxCoeff());
  }
  std::printf("  halving the step: the balance's error falls by %.2f (trapezoid rule: 4)\n", balance[0] / balance[1]);
  return balance;
}
}  // namespace

// The same balance in the nonlinear chain, at large amplitude and with every kind of load the energy does not hold
// (nonconservative_power): on a fixed chain a harmonic and a constant moment, a force (constant and harmonic), joint
// and axial friction, pitch damping and the Magnus moment, and a harmonic field; on a free chain (no gravity) forces on
// both bodies, whose power includes the moving O_1's. H(t) − H(0) = W(t) by the trapezoid rule on the samples: its
// error falls as the output step squared while the tilts are large (0.3 rad).
TEST(ForcedRun, NonlinearEnergyChangesByTheWorkOfItsLoads) {
  const std::string fixed =
      "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\naxial_friction = 0.001\n"
      "[field]\nharmonic = [0.3, -0.2, 1.5]\nfrequency = 0.8\n"
      "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nnext_joint = -0.3\nspin = 30.0\n"
      "[body.moment]\nspace = [0.02, 0.0, 0.01]\nharmonic = [0.0, 0.05, 0.0]\nfrequency = 1.5\n"
      "[body.aero]\npitch_damping = 0.01\nmagnus = 0.0005\n"
      "[[body]]\nmass = 1.0\nA = 0.02\nC = 0.01\ncom = -0.12\nspin = 20.0\n"
      "[body.force]\nat = -0.25\nspace = [0.3, -0.2, -4.0]\nharmonic = [0.5, 0.4, 0.2]\nfrequency = 1.2\n"
      "[[joint]]\nstiffness = 3.0\nfriction = 0.02\n"
      "[initial]\ntilt = [[0.3, 0.0], [-0.2, 0.1]]\n"
      "[run]\nmodel = \"nonlinear\"\nt_end = 4.0\noutput_step = 0.01\ntolerance = 1e-11\n";
  // The free chain: no support, and the first body's moments and aerodynamics replaced by a force.
  const auto cut = [](std::string t, const std::string& from, const std::string& to, const std::string& put) {
    const auto i = t.find(from);
    return t.replace(i, t.find(to, i) - i, put);
  };
  std::string floating = cut(fixed, "kind = \"fixed\"", "[field]", "kind = \"free\"\ngravity = 0.0\n");
  floating = cut(floating, "[body.moment]", "[[body]]", "[body.force]\nat = 0.05\nspace = [0.3, -0.2, 4.0]\n");
  for (const std::string& text : {fixed, floating}) {
    const std::vector<double> balance = nonlinear_balance(text);
    EXPECT_LT(balance[1], 1e-3);
    EXPECT_GT(balance[0] / balance[1], 3.5);
    EXPECT_LT(balance[0] / balance[1], 4.5);
  }
}

namespace {
// In a field varying in space besides gravity: the gradient diag(g_t, g_t, g_z) (symmetric about the spin axis, as the
// linear model needs) and a harmonic transverse field to drive it; tilts and transverse parts times `scale`.
std::string pendulums_in_gradient(double scale, const std::string& model = "method = \"exact\"\n") {
  const auto num = [](double x) { return std::to_string(x); };
  return pendulums_with_field("gradient = [[-20.0, 0.0, 0.0], [0.0, -20.0, 0.0], [0.0, 0.0, 40.0]]\nharmonic = [" +
                                  num(0.05 * scale) + ", " + num(0.04 * scale) + ", 0.0]\nfrequency = 0.8\n",
                              scale, model);
}
}  // namespace

// A field varying in space, f = G x (the scene's [field] gradient; docs/rom.md, "A field that varies in space"). (1)
// A body pivoted at its centre of mass in an orbit's gravity gradient along the local vertical, G = n²(3 e_z e_zᵀ − I):
// the linear chain's characteristic equation is A σ² + C ω σ − 3n²(A − C) = 0 — a prolate body (A > C) librates at
// n √(3(A − C)/A) without spin, an oblate one is thrown over (Beletsky's gravity-gradient libration); (2) two pendulums
// in a gradient besides gravity, driven by a harmonic field: the linear run is the nonlinear chain at small amplitude,
// the difference falling as the amplitude squared; (3) the nonlinear chain keeps its energy (kinetic, gravity's,
// the gradient's potential −½∫xᵀGx dm) with a general symmetric G and bodies with B ≠ A, fixed and free.
TEST(ForcedRun, FieldGradientIsTheGravityGradientsClosedFormAndTheNonlinearChains) {
  const double n = 0.5;
  for (const auto& [A, C, spin] : {std::tuple{0.05, 0.03, 0.0}, std::tuple{0.05, 0.03, 2.0},
                                   std::tuple{0.02, 0.03, 0.0}, std::tuple{0.02, 0.03, 1.0}}) {
    const std::string text = "[system]\nkind = \"fixed\"\ngravity = 0.0\n[field]\ngradient = [[" +
                             std::to_string(-n * n) + ", 0.0, 0.0], [0.0, " + std::to_string(-n * n) +
                             ", 0.0], [0.0, 0.0, " + std::to_string(2 * n * n) + "]]\n[[body]]\nmass = 3.0\nA = " +
                             std::to_string(A) + "\nC = " + std::to_string(C) + "\ncom = 0.0\nspin = " +
                             std::to_string(spin) + "\n";
    const Spectrum sp = compute_spectrum(build_model(parse_scene_text(text, ".", "gravity-gradient")));
    const double Cw = C * spin, K = 3 * n * n * (A - C);
    const cd disc = std::sqrt(cd(Cw * Cw + 4 * A * K));
    std::vector<cd> exact = {(-Cw + disc) / (2 * A), (-Cw - disc) / (2 * A)};
    std::vector<cd> got;
    for (const auto& r : sp.roots) got.push_back(r.sigma);
    ASSERT_EQ(got.size(), 2u);
    const auto by_real = [](cd a, cd b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); };
    std::sort(got.begin(), got.end(), by_real);
    std::sort(exact.begin(), exact.end(), by_real);
    const double err = std::max(std::abs(got[0] - exact[0]), std::abs(got[1] - exact[1])) / std::abs(exact[0]);
    std::printf("  A = %.2f, C = %.2f, spin %.1f: roots %.10f%+.10fi, %.10f%+.10fi; closed form to %.1e (%s)\n", A, C,
                spin, got[0].real(), got[0].imag(), got[1].real(), got[1].imag(), err,
                sp.stable ? "stable" : "unstable");
    EXPECT_LT(err, 1e-12);
    EXPECT_EQ(sp.stable, Cw * Cw + 4 * A * K > 0);
  }
  const std::vector<double> rel = linear_against_nonlinear(pendulums_in_gradient);
  std::printf("  two pendulums in a gradient: halving tilts and field, the difference falls by %.2f (amplitude "
              "squared: 4)\n", rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.5);
  for (const std::string kind : {"fixed", "free"}) {
    const std::string text =
        "[system]\nkind = \"" + kind + "\"\ngravity = 0.0\n[field]\n"
        "gradient = [[-3.0, 0.4, 0.2], [0.4, -2.0, -0.3], [0.2, -0.3, 5.0]]\n"
        "[[body]]\nmass = 2.0\nA = 0.05\nB = 0.04\nC = 0.03\ncom = -0.1\nnext_joint = -0.3\nspin = 30.0\n"
        "[[body]]\nmass = 1.0\nA = 0.02\nC = 0.01\ncom = -0.12\nspin = 20.0\n[[joint]]\nstiffness = 3.0\n"
        "[initial]\ntilt = [[0.3, 0.0], [-0.2, 0.1]]\n"
        "[run]\nmodel = \"nonlinear\"\nt_end = 2.0\noutput_step = 0.01\ntolerance = 1e-11\n";
    const Scene s = parse_scene_text(text, ".", "gradient-energy");
    const NonlinearChain chain = nonlinear_chain(s);
    const NonlinearHistory h = integrate_nonlinear(chain, nonlinear_initial_state(s, chain), s.run);
    std::printf("  nonlinear %s chain in a general gradient, tilts to %.2f rad: energy drift %.1e (H from %.6f to "
                "%.6f)\n", kind.c_str(), h.base.u.cwiseAbs().maxCoeff(), h.base.max_energy_drift, h.base.H.front(),
                h.base.H.back());
    EXPECT_LT(h.base.max_energy_drift, 1e-8);
    // The gradient must matter: without it the tilts go elsewhere.
    std::string plain = text;
    plain.replace(plain.find("gradient = "), plain.find("\n[[body]]") - plain.find("gradient = "), "");
    const Scene s0 = parse_scene_text(plain, ".", "gradient-energy-without");
    const NonlinearChain c0 = nonlinear_chain(s0);
    const NonlinearHistory h0 = integrate_nonlinear(c0, nonlinear_initial_state(s0, c0), s0.run);
    const double moved = (h.base.u - h0.base.u).cwiseAbs().maxCoeff() / h0.base.u.cwiseAbs().maxCoeff();
    std::printf("    without the gradient the tilts differ by %.2f of their largest\n", moved);
    EXPECT_GT(moved, 1e-2);
  }
}
