// The spins' own block of the linear chain (rom/model/axial_rotation.hpp): its roots against Batyr's Lemma 1 and
// Properties 1, 7 and 10 (the zero root's multiplicity and Jordan chains, measured on the first-order matrix by rank),
// the friction rates against an independent generalised eigen-solve, and the closed-form spins against the nonlinear
// chain's. Every comparison prints its figure.
#include "axial_rotation.hpp"
#include "chain_model.hpp"
#include "nonlinear_run.hpp"
#include "propagation.hpp"
#include "rom_test_util.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace rc::rom;

namespace {

// Three bodies; `support` and `joint` axial frictions (N m s), axial moments on the last body.
std::string three_bodies(double support, double joint, double moment, double harmonic, const std::string& run) {
  const auto num = [](double x) { return std::to_string(x); };
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\naxial_friction = " + num(support) +
         "\n[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nnext_joint = -0.2\nspin = 30.0\n"
         "[[body]]\nmass = 1.5\nA = 0.03\nC = 0.02\ncom = -0.1\nnext_joint = -0.2\nspin = 25.0\n"
         "[[body]]\nmass = 1.0\nA = 0.02\nC = 0.01\ncom = -0.1\nspin = 20.0\n"
         "[body.moment]\naxial = " + num(moment) + "\nharmonic = [0.0, 0.0, " + num(harmonic) + "]\nfrequency = 0.5\n"
         "[[joint]]\nfriction = 0.01\naxial_friction = " + num(joint) + "\n[[joint]]\nfriction = 0.01\naxial_friction = " +
         num(joint) + "\n" + run;
}

// rank of the first-order matrix of the axial block [[0, I], [0, −C⁻¹D]] and of its square: the zero root's
// eigenvectors are 2n − rank(A), its Jordan chains of length two rank(A) − rank(A²).
std::pair<int, int> ranks(const AxialChain& a) {
  const int n = static_cast<int>(a.C.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomRightCorner(n, n) = -(a.C.cwiseInverse().asDiagonal() * a.D);
  const auto rank = [](const Eigen::MatrixXd& M) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
    lu.setThreshold(1e-10);
    return static_cast<int>(lu.rank());
  };
  return {rank(A), rank(A * A)};
}

// The three bodies' spins by the linear block's closed form and by the nonlinear chain from the same scene text
// (`run` holds [initial] and [run]): their largest difference and the linear spins' largest change from t = 0.
struct SpinComparison {
  History linear;
  NonlinearHistory nonlinear;
  double diff = 0, change = 0;
};
SpinComparison spins_against_nonlinear(double support, double joint, double moment, double harmonic,
                                       const std::string& run) {
  SpinComparison c;
  const Scene s = parse_scene_text(three_bodies(support, joint, moment, harmonic, run), ".", "axial");
  c.linear = propagate(build_model(s), s);
  const Scene sn = parse_scene_text(three_bodies(support, joint, moment, harmonic, run + "model = \"nonlinear\"\n"),
                                    ".", "nl");
  const NonlinearChain chain = nonlinear_chain(sn);
  c.nonlinear = integrate_nonlinear(chain, nonlinear_initial_state(sn, chain), sn.run);
  EXPECT_EQ(c.linear.spin.rows(), static_cast<Eigen::Index>(c.nonlinear.base.t.size()));
  for (Eigen::Index j = 0; j < c.linear.spin.rows(); ++j)
    for (int k = 0; k < 3; ++k) {
      c.diff = std::max(c.diff, std::abs(c.linear.spin(j, k) - c.nonlinear.spins[j * 3 + k]));
      c.change = std::max(c.change, std::abs(c.linear.spin(j, k) - c.linear.spin(0, k)));
    }
  return c;
}

}  // namespace

// Batyr's Property 7 (no friction: σ = 0 2n-fold with n chains), Property 1 / Theorem 6 (friction to the support:
// σ = 0 n-fold, no chain, and n positive rates), and a chain without the support's friction (the common rotation
// keeps one chain).
TEST(AxialRotation, ZeroRootsAndRatesAreBatyrs) {
  struct Case {
    double support, joint;
    int zeros, chains;
  };
  for (const Case c : {Case{0, 0, 6, 3}, Case{0.02, 0.004, 3, 0}, Case{0, 0.004, 4, 1}}) {
    const ChainModel m = build_model(parse_scene_text(three_bodies(c.support, c.joint, 0, 0, ""), ".", "axial"));
    const AxialSpectrum s = axial_spectrum(m.axial);
    const auto [r1, r2] = ranks(m.axial);
    const int n = 3, eigenvectors = 2 * n - r1, chains = r1 - r2;
    std::printf("support %.3f, joints %.3f: sigma = 0 x %d, %d eigenvectors, %d Jordan chains (ranks of A, A^2: %d, "
                "%d: %d eigenvectors, %d chains)\n", c.support, c.joint, s.zeros, s.zero_eigenvectors,
                s.zeros - s.zero_eigenvectors, r1, r2, eigenvectors, chains);
    EXPECT_EQ(s.zeros, c.zeros);
    EXPECT_EQ(s.zeros - s.zero_eigenvectors, c.chains);
    EXPECT_EQ(chains, c.chains);
    EXPECT_EQ(s.roots.size(), 6u);
    // The rates: the generalised eigenvalues of (D, C), independently.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ge(m.axial.D, Eigen::MatrixXd(m.axial.C.asDiagonal()));
    double worst = 0;
    for (int j = 0; j < n; ++j) worst = std::max(worst, std::abs(ge.eigenvalues()[j] - s.decay[j]));
    std::printf("  rates %.9g %.9g %.9g 1/s, against the generalised eigen-solve: %.1e\n", s.decay[0], s.decay[1],
                s.decay[2], worst);
    EXPECT_LT(worst, 1e-12 * std::max(1.0, ge.eigenvalues().maxCoeff()));
  }
}

// The linear run's spins (closed form) against the nonlinear chain's at a small tilt: axial friction to the support
// and between the bodies, a constant and a harmonic axial moment on the top body. At zero tilt the two are the same
// equations (the nonlinear chain's only to its integrator's tolerance); a tilt of 1e-3 rad changes them at second order.
TEST(AxialRotation, SpinsAreTheNonlinearChains) {
  const std::string run = "[initial]\ntilt = [[0.001, -0.0005], [0.0, 0.0], [0.0, 0.0]]\n"
                          "[run]\nt_end = 5.0\noutput_step = 0.01\ntolerance = 1e-11\n";
  const SpinComparison c = spins_against_nonlinear(0.02, 0.004, 0.01, 0.005, run);
  const History& linear = c.linear;
  const double diff = c.diff, change = c.change;
  std::printf("spins over 5 s: largest change %.4f rad/s; linear closed form against the nonlinear chain %.2e rad/s "
              "(%.1e of the change)\n", change, diff, diff / change);
  EXPECT_GT(change, 0.5);
  EXPECT_LT(diff, 1e-6 * change);
  // ψ is the integral of ω − ω0: its last value against the trapezoid sum of the spins.
  double integral = 0;
  for (Eigen::Index j = 1; j < linear.spin.rows(); ++j)
    integral += 0.5 * 0.01 * (linear.spin(j, 2) + linear.spin(j - 1, 2) - 2 * 20.0);
  const double last = linear.axial_angle(linear.spin.rows() - 1, 2);
  std::printf("top body's angle gained: %.9f rad (trapezoid sum of its spin %.9f)\n", last, integral);
  EXPECT_NEAR(last, integral, 1e-4 * std::abs(last));
}

// A change of spin at t = 0 ([initial] axial_rate). Without axial friction it is Batyr's (89): each spin keeps
// ω_k0 + δ_k and gains the angle δ_k t. With friction to the support and in the joints the spins fall back, the linear
// block's closed form against the nonlinear chain (its own integrator, at a small tilt).
TEST(AxialRotation, AnInitialSpinChangeIsBatyrsUniformRotationOrDecays) {
  const double delta[3] = {0.5, -0.3, 0.2};
  const std::string initial = "[initial]\ntilt = [[0.001, -0.0005], [0.0, 0.0], [0.0, 0.0]]\naxial_rate = [0.5, -0.3, 0.2]\n";
  const std::string run = "[run]\nt_end = 5.0\noutput_step = 0.01\ntolerance = 1e-11\n";
  const Scene free = parse_scene_text(three_bodies(0, 0, 0, 0, initial + run), ".", "axial_free");
  const History uniform = propagate(build_model(free), free);
  ASSERT_GT(uniform.spin.rows(), 0) << "a change of spin moves the spins' block";
  const Eigen::Index last = uniform.spin.rows() - 1;
  const double t_end = uniform.t[last], spins[3] = {30.0, 25.0, 20.0};
  double worst89 = 0;
  for (int k = 0; k < 3; ++k)
    for (Eigen::Index j = 0; j <= last; ++j)
      worst89 = std::max({worst89, std::abs(uniform.spin(j, k) - spins[k] - delta[k]),
                          std::abs(uniform.axial_angle(j, k) - delta[k] * uniform.t[j])});
  std::printf("no axial friction: spins and angles against Batyr (89), omega_k0 + delta_k and delta_k t over %.0f s: "
              "%.1e\n", t_end, worst89);
  EXPECT_LT(worst89, 1e-12);

  const SpinComparison c = spins_against_nonlinear(0.02, 0.004, 0, 0, initial + run);
  const History& linear = c.linear;
  const NonlinearHistory& nl = c.nonlinear;
  const double diff = c.diff, change = c.change;
  std::printf("with axial friction: the spins fall back by up to %.4f rad/s over 5 s; the linear closed form against "
              "the nonlinear chain %.2e rad/s (%.1e of the change); at t = 0 the nonlinear chain's spins are "
              "omega_k0 + delta_k to %.1e\n", change, diff, diff / change,
              std::max({std::abs(nl.spins[0] - spins[0] - delta[0]), std::abs(nl.spins[1] - spins[1] - delta[1]),
                        std::abs(nl.spins[2] - spins[2] - delta[2])}));
  EXPECT_GT(change, 0.1);
  EXPECT_LT(diff, 1e-6 * change);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(nl.spins[k], spins[k] + delta[k], 1e-9);
    EXPECT_NEAR(linear.spin(0, k), spins[k] + delta[k], 1e-9);
  }
}

namespace {
// One body on the support with an axisymmetric tank (tanks = 1: (26)'s path) or two on its axis (tanks = 2: the chain
// without axial symmetry and its nonlinear tanks), axial friction to the support and an axial moment, no tilt.
std::string axial_tank_body(int tanks, const std::string& table, const std::string& run) {
  std::string s = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\naxial_friction = 0.02\n"
                  "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nspin = 30.0\n"
                  "[body.moment]\naxial = 0.01\n";
  for (int j = 0; j < tanks; ++j)
    s += "[[body.cavity]]\ntable = \"" + table + "\"\ndensity = 1000.0\nscale = " + (tanks == 1 ? "0.08" : "0.0635") +
         "\ncenter = " + (j == 0 ? "-0.1" : "-0.25") + "\n";
  return s + run;
}
}  // namespace

// An ideal liquid does not follow its tank's turns about the symmetry axis (docs/physics.md §3, "Axial rotations"):
// the spin under a support's axial friction β and an axial moment M is M/β + (ω0 − M/β) exp(−βt/C) with C the
// shell's, in the linear block, the nonlinear chain (the liquid as a gyrostat's momentum) and the chain without axial
// symmetry (two tanks: the liquid's λ = 0 weight). A liquid spun up with its tank (C + C_f: 11 % more) would not.
TEST(AxialRotation, AnIdealLiquidDoesNotFollowTheSpin) {
  const std::string table = rc::rom::test::spheroid_file(1, 0.6);
  const std::string run = "[run]\nt_end = 3.0\noutput_step = 0.01\ntolerance = 1e-11\n";
  const double beta = 0.02, M = 0.01, C = 0.03, w0 = 30;
  const auto closed = [&](double t, double inertia) { return M / beta + (w0 - M / beta) * std::exp(-beta * t / inertia); };
  const Scene one = parse_scene_text(axial_tank_body(1, table, run), rc::rom::test::test_dir(), "one");
  const double C_f = build_model(one).bodies[0].C - C;
  const History linear = propagate(build_model(one), one);
  double worst = 0, spun_up = 0;
  for (Eigen::Index j = 0; j < linear.spin.rows(); ++j) {
    const double t = 0.01 * static_cast<double>(j);
    worst = std::max(worst, std::abs(linear.spin(j, 0) - closed(t, C)));
    spun_up = std::max(spun_up, std::abs(closed(t, C + C_f) - closed(t, C)));
  }
  const double change = std::abs(closed(3.0, C) - w0);
  std::printf("  C_f = %.4g kg m^2 (%.0f %% of the shell's); linear spin against the closed form %.1e rad/s; the "
              "liquid spun up would move it by %.2e (of a change of %.4f rad/s)\n", C_f, 100 * C_f / C, worst, spun_up,
              change);
  EXPECT_LT(worst, 1e-12 * change);
  EXPECT_GT(spun_up, 0.03 * change);
  for (int tanks : {1, 2}) {
    const Scene sn =
        parse_scene_text(axial_tank_body(tanks, table, run + "model = \"nonlinear\"\n"), rc::rom::test::test_dir(), "nl");
    const NonlinearChain chain = nonlinear_chain(sn);
    EXPECT_EQ(chain.bodies[0].volume.present(), tanks == 2) << "the path of the chain without axial symmetry";
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(sn, chain), sn.run);
    double diff = 0;
    for (std::size_t j = 0; j < nl.base.t.size(); ++j) diff = std::max(diff, std::abs(nl.spins[j] - closed(nl.base.t[j], C)));
    std::printf("  nonlinear chain, %d tank%s: spin against the closed form %.2e rad/s\n", tanks, tanks == 1 ? "" : "s",
                diff);
    EXPECT_LT(diff, 1e-6 * change);
  }
}
