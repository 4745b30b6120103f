// A projectile's aerodynamic moments ([body.aero], linear aeroballistics): the roots against the tricyclic theory's
// closed form, the gyroscopic stability factor's threshold, and the nonlinear chain at small amplitude.
#include "chain_model.hpp"
#include "nonlinear_run.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace rc::rom;
using cd = std::complex<double>;

namespace {

// One body about its centre of mass (com = 0, no gravity): the projectile of docs/rom.md's mapping.
std::string projectile(double spin, double static_moment, double damping, double tilt = 0.0, const std::string& run = "",
                       double magnus = 0.0) {
  const auto num = [](double x) { return std::to_string(x); };
  return "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 2.0\nA = 0.025\nC = 0.004\ncom = 0.0\nspin = " +
         num(spin) + "\n[body.aero]\nstatic_moment = " + num(static_moment) + "\npitch_damping = " + num(damping) +
         "\nmagnus = " + num(magnus) +
         "\n[initial]\ntilt = [[" + num(tilt) + ", " + num(0.5 * tilt) + "]]\n" + run;
}

}  // namespace

// The tricyclic theory (epicyclic yaw of a spinning shell, e.g. McCoy, "Modern Exterior Ballistics", 1999, ch. 10, in
// time instead of arc length, no lift or Magnus): A ü + (iCω + M_q) u̇ − M_α u = 0, so with P = Cω/A, H = M_q/A,
// M = M_α/A the roots of e^{iσt} solve σ² + (P − iH)σ + M = 0. Their growth rates −Im σ are, to first order in H,
// the arms' damping exponents λ_{1,2} = −(H/2)(1 ± P/√(P² − 4M)): the fast (nutation) arm decays, the slow
// (precession) arm grows — pitch damping alone destabilises an overturning shell (Kelvin–Tait–Chetaev).
TEST(Aero, RootsAreTheTricyclicArms) {
  const double A = 0.025, C = 0.004, w = 3000, Ma = 40, Mq = 0.002;
  const Spectrum sp = compute_spectrum(build_model(parse_scene_text(projectile(w, Ma, Mq), ".", "shell")));
  ASSERT_EQ(sp.roots.size(), 2u);
  const cd P = C * w / A, H = Mq / A, M = Ma / A;
  const cd d = std::sqrt((P - cd(0, 1) * H) * (P - cd(0, 1) * H) - 4.0 * M);
  const cd exact[2] = {(-(P - cd(0, 1) * H) - d) / 2.0, (-(P - cd(0, 1) * H) + d) / 2.0};  // fast, slow
  double worst = 0;
  for (const cd& e : exact) {
    double nearest = 1e300;
    for (const Root& r : sp.roots) nearest = std::min(nearest, std::abs(r.sigma - e) / std::abs(e));
    worst = std::max(worst, nearest);
  }
  const double root = std::sqrt(P.real() * P.real() - 4 * M.real());
  const double lam_fast = -(H.real() / 2) * (1 + P.real() / root), lam_slow = -(H.real() / 2) * (1 - P.real() / root);
  const Root& fast = std::abs(sp.roots[0].sigma) > std::abs(sp.roots[1].sigma) ? sp.roots[0] : sp.roots[1];
  const Root& slow = &fast == &sp.roots[0] ? sp.roots[1] : sp.roots[0];
  const double first_order = std::max(std::abs(-fast.sigma.imag() - lam_fast) / std::abs(lam_fast),
                                      std::abs(-slow.sigma.imag() - lam_slow) / std::abs(lam_slow));
  std::printf("  S_g = %.3f; roots against the quadratic's closed form %.1e; growth %.6g (fast), %.6g 1/s (slow) "
              "against the tricyclic first-order exponents %.6g, %.6g: %.1e (O(H/P) = %.1e)\n",
              (P * P / (4.0 * M)).real(), worst, -fast.sigma.imag(), -slow.sigma.imag(), lam_fast, lam_slow, first_order,
              H.real() / P.real());
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(first_order, H.real() / P.real());  // second order in H/P: measured 2.9e-8
  EXPECT_FALSE(sp.stable);  // the slow arm grows
}

// Without damping an overturning shell is held by its spin alone: stable iff S_g = C²ω²/(4 A M_α) > 1.
TEST(Aero, GyroscopicStabilityFactorIsTheThreshold) {
  const double A = 0.025, C = 0.004, Ma = 40;
  const double w_star = std::sqrt(4 * A * Ma) / C;  // S_g = 1
  for (double f : {0.99, 1.01}) {
    const Verdict v = compute_verdict(build_model(parse_scene_text(projectile(f * w_star, Ma, 0), ".", "shell")));
    std::printf("  S_g = %.4f: %s (margin %.3g rad/s)\n", f * f, v.stable ? "stable" : "unstable", v.margin);
    EXPECT_EQ(v.stable, f > 1);
  }
}

// With a Magnus moment M_p ω u (along the yaw's direction, F = i M_p ω u): A ü + (iCω + M_q)u̇ − (M_α + i M_p ω)u = 0,
// the roots of A σ² + (Cω − i M_q)σ + M_α + i M_p ω = 0.
TEST(Aero, MagnusRootsAreTheQuadratics) {
  const double A = 0.025, C = 0.004, w = 3000, Ma = 40, Mq = 0.002, Mp = 1e-4;
  const Spectrum sp = compute_spectrum(build_model(parse_scene_text(projectile(w, Ma, Mq, 0, "", Mp), ".", "shell")));
  ASSERT_EQ(sp.roots.size(), 2u);
  const cd b = C * w - cd(0, Mq), c = Ma + cd(0, Mp * w);
  const cd d = std::sqrt(b * b - 4.0 * A * c);
  double worst = 0;
  for (const cd& e : {(-b - d) / (2 * A), (-b + d) / (2 * A)}) {
    double nearest = 1e300;
    for (const Root& r : sp.roots) nearest = std::min(nearest, std::abs(r.sigma - e) / std::abs(e));
    worst = std::max(worst, nearest);
  }
  std::printf("  Magnus %.0e N m/(rad rad/s): roots against the quadratic %.1e; growth %.4g and %.4g 1/s\n", Mp, worst,
              -sp.roots[0].sigma.imag(), -sp.roots[1].sigma.imag());
  EXPECT_LT(worst, 1e-12);
}

// The nonlinear chain with the same moments (static M_α e_z × n, damping on the transverse angular velocity, Magnus
// M_p s (n − n_z e_z)) at small yaw: the difference from the linear run relative to the amplitude falls as the
// amplitude squared — which also checks that the two models give the Magnus moment the same sense.
TEST(Aero, NonlinearChainAtSmallYawIsTheLinearOne) {
  std::vector<double> rel;
  for (double yaw : {0.02, 0.01}) {
    const std::string run = "[run]\nt_end = 0.5\noutput_step = 0.005\n";
    const Scene s = parse_scene_text(projectile(300, 4, 0.01, yaw, run + "method = \"exact\"\n", 0.002), ".", "shell");
    const History linear = propagate(build_model(s), s);
    const Scene sn = parse_scene_text(projectile(300, 4, 0.01, yaw, run + "model = \"nonlinear\"\ntolerance = 1e-12\n", 0.002),
                                      ".", "shell-nl");
    const NonlinearChain chain = nonlinear_chain(sn);
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(sn, chain), sn.run);
    double diff = 0;
    for (Eigen::Index j = 0; j < linear.u.rows(); ++j) diff = std::max(diff, std::abs(linear.u(j, 0) - nl.base.u(j, 0)));
    rel.push_back(diff / linear.u.cwiseAbs().maxCoeff());
    std::printf("  yaw %.2f rad (S_g 3.6, damping 0.01, Magnus 0.002): nonlinear against linear %.2e of the amplitude\n",
                yaw, rel.back());
  }
  std::printf("  halving the yaw: the difference falls by %.2f (amplitude squared: 4)\n", rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.5);
}
