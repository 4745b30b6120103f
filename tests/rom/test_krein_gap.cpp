// The distance to the threshold of a stable undamped chain (krein_gap.hpp): the closest real roots of opposite
// Krein signature, against the heavy top's closed form and the signatures against the roots' own motion.
#include "krein_gap.hpp"
#include "rom_test_util.hpp"
#include "spectrum.hpp"
#include "sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rc::rom;
using namespace rc::rom::test;

// Heavy top without fluid: A σ² + C ω σ + a g = 0 (Kononov (22) for one body, roots of e^{iσt}), so the two roots
// σ± = (−C ω ± sqrt(C²ω² − 4 A a g)) / 2A are real above ω* = sqrt(4 A a g)/C, of opposite signature, and meet at ω*:
// the gap is sqrt(C²ω² − 4 A a g)/A, 0 at the threshold, undefined below it.
TEST(KreinGap, HeavyTopGapIsTheClosedForm) {
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1;
  const Scene s = parse_scene_text(scene_text({b}, {}, 9.81), test_dir(), "test-scene");
  const double A = 0.05, a = 0.2, g = 9.81, C = 0.03;
  const double w_star = std::sqrt(4 * A * a * g) / C;
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, SweepAxis{parse_param_key("body[1].spin", s), 0, 40, 401}, std::nullopt, 2);
  double worst = 0;
  int defined = 0;
  for (const SweepPoint& p : r.points) {
    ASSERT_TRUE(p.ok) << p.error;
    const double d = C * C * p.v1 * p.v1 - 4 * A * a * g;
    if (d < 1e-9) {
      EXPECT_TRUE(std::isnan(p.gap)) << "spin " << p.v1;
      continue;
    }
    ++defined;
    worst = std::max(worst, std::abs(p.gap - std::sqrt(d) / A) / (std::abs(C * p.v1) / A));
  }
  Scene t = s;
  t.bodies[0].spin = 1.001 * w_star;  // just above the threshold: the spectrum's gap and its two roots
  const Spectrum sp = compute_spectrum(build_model(t));
  ASSERT_TRUE(sp.krein.defined);
  const double d = C * C * t.bodies[0].spin * t.bodies[0].spin - 4 * A * a * g;
  std::printf("  w* = %.6f rad/s; %d stable points: gap against sqrt(C^2 w^2 - 4Aag)/A to %.1e of C w/A; "
              "at 1.001 w*: %.6e rad/s (closed form %.6e)\n", w_star, defined, worst, sp.krein.gap, std::sqrt(d) / A);
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(defined, 100);
  EXPECT_NEAR(sp.krein.gap, std::sqrt(d) / A, 1e-9 * C * t.bodies[0].spin / A);
}

// The signature read from Φ against the roots' motion: adding ε to every diagonal entry of the inertia (M and M_eff)
// moves a simple real root by dσ/dε = −|v|²/(vᵀΦ'(σ)v), so its sign is minus the signature. Two bodies with spheroid
// tanks (body and fluid roots), at spin factors where the chain is stable.
TEST(KreinGap, SignatureIsHowTheRootMovesWhenInertiaGrows) {
  Body b1; b1.mass = 2; b1.A = 0.1; b1.C = 0.08; b1.com = 0.1; b1.next = 0.3; b1.spin = 50;
  b1.table = spheroid_file(1.0, 1.6); b1.scale = 0.05; b1.center = 0.12;
  Body b2; b2.mass = 1; b2.A = 0.03; b2.C = 0.02; b2.com = 0.06; b2.spin = 70;
  b2.table = spheroid_file(1.0, 0.7); b2.scale = 0.04; b2.center = 0.05;
  const Scene s = parse_scene_text(scene_text({b1, b2}, {{3.0, 0.0}}, 9.81), test_dir(), "test-scene");
  int checked = 0, gaps = 0;
  for (double factor : {1.0, 1.5, 2.0, 3.0}) {
    Scene t = s;
    t.bodies[0].spin *= factor;
    t.bodies[1].spin *= factor;
    const ChainModel m = build_model(t);
    const Eigen::VectorXcd sigma = verdict_roots(m);
    const Verdict v = verdict_from_roots(m, sigma);
    if (!v.stable) continue;
    ChainModel heavier = m;
    const double eps = 1e-7 * m.M.diagonal().cwiseAbs().maxCoeff();
    heavier.M.diagonal().array() += eps;
    heavier.M_eff.diagonal().array() += eps;
    const Eigen::VectorXcd moved = verdict_roots(heavier);
    for (Eigen::Index j = 0; j < sigma.size(); ++j) {
      if (std::abs(sigma[j]) <= v.tolerance) continue;
      const int sig = krein_signature(m, sigma[j].real());
      if (sig == 0) continue;
      Eigen::Index k = 0;
      (moved.array() - sigma[j]).abs().minCoeff(&k);
      const double shift = moved[k].real() - sigma[j].real();
      if (std::abs(shift) < 1e-9 * v.radius) continue;  // too small to tell from rounding
      EXPECT_EQ(shift > 0 ? 1 : -1, -sig) << "factor " << factor << ", root " << sigma[j].real();
      ++checked;
    }
    gaps += krein_gap(m, sigma, v.tolerance).defined ? 1 : 0;
  }
  std::printf("  %d real roots: the signature from v'Phi'v is minus the direction each moves when inertia grows; "
              "%d stable factors with a gap\n", checked, gaps);
  EXPECT_GT(checked, 10);
  EXPECT_GT(gaps, 0);
}
