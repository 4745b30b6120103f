// Stiff and extreme scenes: spins to 1e4 rad/s, joint stiffness to 1e8, 200 kept modes,
// n = 100 bodies, near-massless shells, cavities of aspect 1/50 and 50. Each must give finite roots,
// a small det residual of (22)/(29) and the verdict of an independent criterion; exact propagation
// keeps the energy on the stiff and fast scenes; gauss and rk45 refuse runs they cannot finish.
// Bounds are the measured worst values times about 10 (docs/rom.md, "Limits").
#include "characteristic.hpp"
#include "propagation.hpp"
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

namespace {

bool all_finite(const Spectrum& sp) {
  for (const auto& r : sp.roots)
    if (!std::isfinite(r.sigma.real()) || !std::isfinite(r.sigma.imag())) return false;
  return std::isfinite(sp.margin) && std::isfinite(sp.det_residual);
}

std::string run_section(double t_end, double step, const std::string& method, int n, double tol = 1e-10) {
  std::string tilt = "tilt = [", rate = "rate = [";
  for (int k = 0; k < n; ++k) {
    tilt += std::string(k ? ", " : "") + "[" + num(0.01 * (k % 2 ? -1 : 1)) + ", " + num(0.002 * k) + "]";
    rate += std::string(k ? ", " : "") + "[0.0, " + num(0.05 * (k + 1)) + "]";
  }
  return "[initial]\n" + tilt + "]\n" + rate + "]\n[run]\nt_end = " + num(t_end) + "\noutput_step = " + num(step) +
         "\nmethod = \"" + method + "\"\ntolerance = " + num(tol) + "\n";
}

// Roots of the E = 0 heavy top A' s^2 + C w s + a g = 0 (Kononov (23) without fluid).
std::vector<cd> top_roots(double A, double Cw, double ag) {
  const cd disc = std::sqrt(cd(Cw * Cw - 4 * A * ag));
  return {(-Cw + disc) / (2 * A), (-Cw - disc) / (2 * A)};
}

// Stiff chain: five bodies (fluid in 1, 3, 5) on joints of stiffness kap, spinning at 100 rad/s.
std::vector<Body> stiff_bodies() {
  std::vector<Body> b(5);
  for (int k = 0; k < 5; ++k) {
    b[k].mass = 2.0 - 0.2 * k; b[k].A = 0.05 + 0.01 * k; b[k].C = 0.06; b[k].com = 0.08; b[k].next = 0.2;
    b[k].spin = 100;
    if (k % 2 == 0) { b[k].table = spheroid_file(1, 0.6); b[k].scale = 0.04; b[k].center = 0.06; }
  }
  return b;
}
std::string stiff_text(double kap, const std::string& extra = "") {
  return scene_text(stiff_bodies(), std::vector<Joint>(4, Joint{kap, 0}), 9.81, false, 0, extra);
}

// Fast heavy tops: two bodies with oblate cavities at 1e4 and 8e3 rad/s, elastic joint.
std::string fast_text(double spin, const std::string& extra = "") {
  Body b1; b1.mass = 2; b1.A = 0.05; b1.C = 0.08; b1.com = 0.05; b1.next = 0.15; b1.spin = spin;
  b1.table = spheroid_file(1, 0.6); b1.scale = 0.04; b1.center = 0.05;
  Body b2; b2.mass = 1; b2.A = 0.02; b2.C = 0.035; b2.com = 0.04; b2.spin = 0.8 * spin;
  b2.table = spheroid_file(1, 0.7); b2.scale = 0.03; b2.center = 0.04;
  return scene_text({b1, b2}, {{5.0, 0}}, 9.81, false, 0, extra);
}

}  // namespace

// One heavy top without fluid from 1e2 to 1e4 rad/s: roots against the quadratic, verdict by
// C^2 w^2 > 4 A' a g (stable) and, with a g raised to 1.1 times the threshold, unstable.
TEST(Extreme, HeavyTopTo1e4RadPerSecond) {
  double worst_err = 0, worst_res = 0;
  for (double spin : {1e2, 1e3, 1e4}) {
    for (double over : {0.0, 1.1}) {  // 0: g = 9.81; 1.1: gravity 1.1 x the stability threshold
      const double A = 0.05, C = 0.03, a = 0.2, Cw = C * spin;
      const double g = over > 0 ? over * Cw * Cw / (4 * A * a) : 9.81;
      Body b; b.mass = 2; b.A = A; b.C = C; b.com = 0.1; b.spin = spin;
      const Spectrum sp = compute_spectrum(model_of(scene_text({b}, {}, g)));
      ASSERT_TRUE(all_finite(sp));
      const auto exact = top_roots(A, Cw, a * g);
      const double err = root_set_distance(roots_of(sp), exact, spectral_radius(exact));
      worst_err = std::max(worst_err, err);
      worst_res = std::max(worst_res, sp.det_residual);
      EXPECT_EQ(sp.stable, Cw * Cw > 4 * A * a * g) << "spin " << spin << " g " << g;
      EXPECT_LT(err, 1e-12) << "spin " << spin;
    }
  }
  std::printf("  heavy top 1e2..1e4 rad/s: root error %.2e, det residual %.2e\n", worst_err, worst_res);
  EXPECT_LT(worst_res, 1e-13);
}

// Two tops with fluid at 1e4 rad/s: finite roots, det residual, gyroscopic stability (the gravity
// torque is 1e-6 of C w^2: each top is deep inside C^2 w^2 > 4 A' a g and the cavities are oblate,
// Greenhill-stable); exact propagation keeps H to 1e-10.
TEST(Extreme, FluidTopsAt1e4RadPerSecondKeepEnergy) {
  const ChainModel m = model_of(fast_text(1e4));
  const Spectrum sp = compute_spectrum(m);
  ASSERT_TRUE(all_finite(sp));
  for (int k = 0; k < m.n; ++k)
    EXPECT_GT(std::pow(m.G[k], 2), 1e4 * 4 * m.M(k, k) * m.a[k] * m.g);  // independent: far inside the top criterion
  double smallest = 1e300;
  for (const auto& r : sp.roots) smallest = std::min(smallest, std::abs(r.sigma));
  std::printf("  1e4 rad/s, %zu roots, |sigma| %.3e..%.3e, det residual %.2e, stable %d, margin %.2e\n",
              sp.roots.size(), smallest,
              spectral_radius(roots_of(sp)), sp.det_residual, sp.stable, sp.margin);
  EXPECT_TRUE(sp.stable);
  EXPECT_LT(sp.det_residual, 4e-10);  // measured 3.8e-11 (roots from 2.9e-3 to 1.5e4 rad/s)

  const double fastest = spectral_radius(roots_of(sp));
  const double t_end = 200 * 2 * M_PI / fastest * 50;  // 1e4 periods of the fastest root
  const Scene s = parse_scene_text(fast_text(1e4, run_section(t_end, t_end / 2000, "exact", 2)), test_dir(), "fast");
  const History h = propagate(build_model(s), s);
  std::printf("  %s over %.3g s: energy drift %.2e, cond(V) %.2e\n", h.method_used.c_str(), t_end,
              h.max_energy_drift, h.eigvec_condition);
  EXPECT_LT(h.max_energy_drift, 1e-10);
  EXPECT_TRUE(h.u.allFinite());
}

// Joints of stiffness 1e2..1e8: the high-frequency roots tend to +-sqrt of the generalised eigenvalues
// of (K, M_eff) (at |sigma| -> inf Phi -> M_eff - K/sigma^2), the low ones to the chain welded into one
// rigid body (u_1 = ... = u_5); exact propagation keeps H to 1e-10 at 1e8.
TEST(Extreme, StiffJointsTo1e8) {
  // The welded body: u_k = u for all k, i.e. 1^T (Phi(sigma)) 1 = 0 without the elastic terms.
  for (double kap : {1e2, 1e5, 1e8}) {
    const ChainModel m = model_of(stiff_text(kap));
    const Spectrum sp = compute_spectrum(m);
    ASSERT_TRUE(all_finite(sp));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ge(m.K, m.M_eff);
    const double hi_ref = std::sqrt(ge.eigenvalues().maxCoeff());
    const double R = spectral_radius(roots_of(sp));
    // the top branch: the 4 largest elastic frequencies appear as +-pairs shifted by gyroscopic terms
    const double rel = std::abs(R - hi_ref) / hi_ref;
    // Welded body: roots of 1^T Phi_noelastic(sigma) 1 (M, G, gravity, fluid summed); compare the
    // smallest-|sigma| body roots through the det residual of that scalar function.
    double weld = 0;
    if (kap >= 1e5) {
      const Eigen::VectorXcd one = Eigen::VectorXcd::Ones(m.n);
      int checked = 0;
      // the 2 (n - 1) elastic roots are the largest; the others belong to the welded body
      std::vector<cd> low = roots_of(sp);
      std::sort(low.begin(), low.end(), [](cd p, cd q) { return std::abs(p) < std::abs(q); });
      low.resize(low.size() - 2 * (m.n - 1));
      for (const cd sig : low) {
        // the three cavities share one pole sigma = lambda - w: two of the fluid roots sit next to it
        // with the bodies' fluids moving against each other (not a welded-body motion): skipped
        double pole = 1e300;
        for (const auto& md : m.modes) pole = std::min(pole, std::abs(sig + m.bodies[md.body].omega - md.lambda));
        if (pole < 1e-5 * std::abs(sig)) continue;
        const Eigen::MatrixXcd Phi = characteristic_matrix(m, sig);
        // elastic terms vanish on u = 1: 1^T Phi 1 is the welded body's characteristic function
        const cd f = one.dot(Phi * one);
        const double size = one.dot(m.M.cast<cd>() * one).real();
        weld = std::max(weld, std::abs(f) / size);
        ++checked;
      }
      EXPECT_EQ(checked, 3);  // the tilt pair and the welded body's own fluid root
    }
    std::printf("  kappa^2 = %.0e: %zu roots, largest |sigma| %.4e vs sqrt(lambda_max(K, M_eff)) %.4e (rel %.1e);"
                " welded-body residual %.1e; det residual %.2e; stable %d\n",
                kap, sp.roots.size(), R, hi_ref, rel, weld, sp.det_residual, sp.stable);
    // first-order gyroscopic shift of an elastic root: about max_k C_k w_k / M_eff,kk
    double gyro = 0;
    for (int k = 0; k < m.n; ++k) gyro = std::max(gyro, m.G[k] / m.M_eff(k, k));
    if (kap >= 1e5) { EXPECT_LT(rel, gyro / hi_ref); }
    EXPECT_LT(sp.det_residual, 3e-10);
    // measured 9.3e-3 (1e5), 9.4e-6 (1e8): the welded body is approached as 1/kappa^2
    if (kap >= 1e5) { EXPECT_LT(weld, kap >= 1e8 ? 1e-4 : 1e-1); }
  }
  // the fast elastic branch scales as sqrt(kappa^2 / A)
  const double r5 = spectral_radius(roots_of(compute_spectrum(model_of(stiff_text(1e6)))));
  const double r8 = spectral_radius(roots_of(compute_spectrum(model_of(stiff_text(1e8)))));
  std::printf("  |sigma|max(1e8) / |sigma|max(1e6) = %.5f (sqrt scaling: 10)\n", r8 / r5);
  EXPECT_NEAR(r8 / r5, 10.0, 0.1);  // 1e6: gyroscopic shift ~0.6%

  const double fast = r8, slow_period = 2 * M_PI / 100;
  const Scene s = parse_scene_text(stiff_text(1e8, run_section(5 * slow_period, 2 * M_PI / fast / 7, "exact", 5)),
                                   test_dir(), "stiff");
  const ChainModel m = build_model(s);
  const History h = propagate(m, s);
  std::printf("  %s, %zu samples over %.3g s: energy drift %.2e, cond(V) %.2e\n", h.method_used.c_str(), h.t.size(),
              h.t.back(), h.max_energy_drift, h.eigvec_condition);
  EXPECT_LT(h.max_energy_drift, 1e-10);
  EXPECT_TRUE(h.u.allFinite());
}

// gauss and rk45 on the 1e8 stiff chain over 10 s: refused at once with one line naming the method,
// the estimated step count and method = "exact"; the estimate of rk45 matches its real step count on
// a mild scene within a factor 3.
TEST(Extreme, IntegratorsRefuseAbsurdStepCounts) {
  for (const std::string meth : {"gauss", "rk45"}) {
    const Scene s = parse_scene_text(stiff_text(1e8, run_section(10.0, 1e-2, meth, 5)), test_dir(), "stiff.toml");
    const ChainModel m = build_model(s);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      (void)propagate(m, s);
      ADD_FAILURE() << meth << " was not refused";
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("  %s refused in %.3f s: %s\n", meth.c_str(), sec, msg.c_str());
      EXPECT_EQ(msg.find('\n'), std::string::npos);
      EXPECT_NE(msg.find("stiff.toml: run.method: " + meth + " would need about "), std::string::npos);
      EXPECT_NE(msg.find("method = \"exact\""), std::string::npos);
      EXPECT_LT(sec, 1.0);
    }
  }
  // below the limit the same methods run (kappa^2 = 1e2, short horizon), and the rk45 estimate is honest
  const Scene s = parse_scene_text(stiff_text(1e2, run_section(0.2, 1e-3, "rk45", 5)), test_dir(), "mild");
  const ChainModel m = build_model(s);
  const History h = propagate(m, s);
  const Spectrum sp = compute_spectrum(m);
  const double est = estimate_integrator_steps("rk45", spectral_radius(roots_of(sp)), s.run);
  std::printf("  mild scene: rk45 took %ld steps, estimate %.0f (ratio %.2f)\n", h.integrator_steps, est,
              est / h.integrator_steps);
  EXPECT_GT(est / h.integrator_steps, 1.0 / 3);
  EXPECT_LT(est / h.integrator_steps, 3.0);
  EXPECT_EQ(estimate_integrator_steps("exact", 1e9, s.run), 0.0);
}

namespace {
// Lower bound on the number of real roots of a one-body scene without friction: F(sigma) =
// Phi(sigma) is real on the real axis, its sign next to each pole sigma = lambda_l - w is known from the
// residue (-sign(lambda_l) right of it, +sign(lambda_l) left), next to 0 it is sign(a g) (or of C w /
// sigma when a g = 0), at +-inf it is sign(M_eff) > 0; between, F is sampled (64 points per interval).
// Every sign change of this sequence is a real root of sigma^2 prod(sigma + w - lambda_l) F(sigma).
int real_root_lower_bound(const ChainModel& m) {
  struct Sing { double at; int left, right; };
  std::vector<Sing> s;
  const double ag = m.a[0] * m.g, Cw = m.G[0], w = m.bodies[0].omega;
  if (ag != 0) s.push_back({0.0, ag > 0 ? 1 : -1, ag > 0 ? 1 : -1});
  else if (Cw != 0) s.push_back({0.0, Cw > 0 ? -1 : 1, Cw > 0 ? 1 : -1});
  for (const auto& md : m.modes) {
    const int sg = md.lambda > 0 ? 1 : -1;
    s.push_back({md.lambda - w, sg, -sg});
  }
  std::sort(s.begin(), s.end(), [](const Sing& p, const Sing& q) { return p.at < q.at; });
  double R = 1;
  for (const Sing& x : s) R = std::max(R, std::abs(x.at));
  auto F = [&](double x) { return characteristic_matrix(m, cd(x, 0))(0, 0).real(); };
  // Sign changes inside one interval of continuity: [sign at its left end, samples, sign at its right end].
  int changes = 0;
  auto count = [&](int left, const std::vector<double>& xs, int right) {
    int prev = left;
    for (double x : xs) {
      const double v = F(x);
      const int sg = v > 0 ? 1 : (v < 0 ? -1 : 0);
      if (sg != 0 && sg != prev) { ++changes; prev = sg; }
    }
    if (right != prev) ++changes;
  };
  const int N = 64;
  std::vector<double> xs;
  for (int i = N; i >= 1; --i) xs.push_back(s.front().at - 1e-6 * R * std::pow(1e10, double(i) / N));
  count(1, xs, s.front().left);  // (-inf, first singularity); F(-inf) = M_eff > 0
  for (std::size_t j = 0; j + 1 < s.size(); ++j) {
    const double x0 = s[j].at, x1 = s[j + 1].at;
    xs.clear();
    for (int i = 1; i < N; ++i) xs.push_back(x0 + (x1 - x0) * 0.5 * (1 - std::cos(M_PI * i / N)));
    count(s[j].right, xs, s[j + 1].left);
  }
  xs.clear();
  for (int i = 1; i <= N; ++i) xs.push_back(s.back().at + 1e-6 * R * std::pow(1e10, double(i) / N));
  count(s.back().right, xs, 1);  // (last singularity, +inf)
  return changes;
}

// A synthetic table of `count` coupling modes sharing the sum rule of a spheroid a = 1, c = 1.5, with
// E_l decreasing geometrically and lambda_l in (0, 2) distinct (inertial waves: |lambda| < 2).
rc::ModeTable many_mode_table(int count) {
  rc::ModeTable t = spheroid_table(1, 1.5);
  const double S = t.A_f - t.J_zh;
  t.E.clear(); t.lambda.clear(); t.kappa.clear(); t.a.clear(); t.N2.clear(); t.residual.clear();
  double sum = 0;
  for (int l = 0; l < count; ++l) sum += std::pow(0.97, l);
  for (int l = 0; l < count; ++l) {
    t.E.push_back(S * std::pow(0.97, l) / sum);
    const double lam = 1.9 * (l + 0.5) / count;  // 0.00475 .. 1.895, all distinct
    t.lambda.push_back(lam);
    t.kappa.push_back(2 / lam);
    t.a.push_back(std::sqrt(t.E.back() / 2));
    t.N2.push_back(1.0);
    t.residual.push_back(0.0);
  }
  t.coverage = 1;
  return t;
}
}  // namespace

// 200 kept modes in one top. At w = 0 only sum E = A_f - J_zh acts (Batyr Theorem 2): the tilt
// roots equal the rigid body with Zhukovsky's inertia. Spinning: finite roots, small det residual, and
// the verdict against an independent count: F(sigma) is real on the real axis with known signs next to
// each pole sigma = lambda_l - w (-sign(lambda_l) right of it, +sign(lambda_l) left), next to 0 (sign of
// a g) and at +-inf (M_eff > 0); every sign change is a real root, so 202 changes prove all roots real.
TEST(Extreme, TwoHundredModes) {
  write_table(many_mode_table(200), test_dir() / "modes200.h5");
  const rc::ModeTable t = many_mode_table(200);
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.08; b.com = 0.05; b.table = "modes200.h5"; b.scale = 0.04;
  b.center = 0.05;
  // w = 0 against the rigid body with J_zh
  {
    const Spectrum sf = compute_spectrum(model_of(scene_text({b}, {}, 9.81)));
    const double L = b.scale, mf = b.density * L * L * L * t.volume, Jzh = b.density * std::pow(L, 5) * t.J_zh;
    Body r; r.mass = b.mass + mf; r.com = (b.mass * b.com + mf * b.center) / r.mass;
    r.A = b.A + Jzh + mf * b.center * b.center; r.C = b.C; r.spin = 0;
    const Spectrum sr = compute_spectrum(model_of(scene_text({r}, {}, 9.81)));
    const auto tilts = drop_smallest(roots_of(sf), 200);
    const double err = root_set_distance(tilts, roots_of(sr), spectral_radius(roots_of(sr)));
    std::printf("  200 modes, w = 0: tilt roots vs Zhukovsky rigid body %.2e\n", err);
    ASSERT_TRUE(all_finite(sf));
    EXPECT_LT(err, 1e-10);
  }
  // spinning, gravity off (a g = 0 leaves the sign at 0 to C w / sigma) and on
  for (double spin : {300.0, 3000.0}) {
    b.spin = spin;
    const ChainModel m = model_of(scene_text({b}, {}, 9.81));
    const Spectrum sp = compute_spectrum(m);
    ASSERT_TRUE(all_finite(sp));
    const int changes = real_root_lower_bound(m);
    const int degree = 2 + m.n_modes();
    std::printf("  200 modes, w = %g: %zu roots, det residual %.2e, unchecked %d, stable %d; real roots proven by "
                "sign changes: %d of %d\n", spin, sp.roots.size(), sp.det_residual, sp.unchecked, sp.stable, changes,
                degree);
    EXPECT_EQ(static_cast<int>(sp.roots.size()), degree);
    // measured <= 9.6e-9: roots next to poles of tiny E (E_200 = 2.3e-3 E_1) are known only to
    // eps |sigma|max absolutely, which is large relative to their distance from the pole
    EXPECT_LT(sp.det_residual, 1e-7);
    EXPECT_LE(changes, degree);  // a lower bound on the real roots cannot exceed their number
    EXPECT_EQ(changes == degree, sp.stable);  // all roots real, proven independently
  }
}

// n = 100 bodies, each with an oblate cavity, O_k at the centre of mass of the enlarged body k for
// k >= 2 (a_2 = ... = a_100 = 0): (22) splits into (23) for body 1 and (24) for the others; the chain's
// 300 roots must be the union of 100 single-body spectra.
TEST(Extreme, HundredBodiesDecoupleInto23And24) {
  const int n = 100;
  const double s = 0.3, g = 9.81;
  const rc::ModeTable tab = spheroid_table(1, 0.6);
  std::vector<Body> bodies(n);
  std::vector<double> m_tot(n);
  for (int k = 0; k < n; ++k) {
    Body& b = bodies[k];
    b.mass = 1; b.A = 0.02; b.C = 0.03; b.next = s; b.spin = 200 + 2 * k;
    b.table = spheroid_file(1, 0.6); b.scale = 0.03; b.center = 0;
    m_tot[k] = b.mass + b.density * std::pow(b.scale, 3) * tab.volume;
  }
  std::vector<double> tail(n, 0.0);  // sum_{i>k} m_i
  for (int k = n - 2; k >= 0; --k) tail[k] = tail[k + 1] + m_tot[k + 1];
  bodies[0].com = 0.1;
  bodies[0].spin = 5000;  // C^2 w^2 > 4 A'_1 a_1 g with the whole tail hanging on body 1
  for (int k = 1; k < n; ++k) bodies[k].com = -(k + 1 < n ? s * tail[k] : 0.0) / bodies[k].mass;
  bodies[n - 1].com = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const ChainModel m = model_of(scene_text(bodies, std::vector<Joint>(n - 1), g));
  const Spectrum sp = compute_spectrum(m);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(all_finite(sp));
  double amax = 0;
  for (int k = 1; k < n; ++k) amax = std::max(amax, std::abs(m.a[k]));

  std::vector<cd> ref;
  bool ref_stable = true;
  for (int k = 0; k < n; ++k) {
    Body r = bodies[k];
    if (k + 1 < n) r.A += s * s * tail[k];
    r.com = k == 0 ? (bodies[0].mass * bodies[0].com + s * tail[0]) / bodies[0].mass : 0.0;
    const Spectrum one = compute_spectrum(model_of(scene_text({r}, {}, g)));
    ref_stable = ref_stable && one.stable;
    const auto x = roots_of(one);
    ref.insert(ref.end(), x.begin(), x.end());
  }
  const double err = root_set_distance(roots_of(sp), ref, spectral_radius(ref));
  std::printf("  n = 100: max |a_k| (k >= 2) %.1e, %zu roots in %.2f s, vs 100 single bodies %.2e, det residual %.2e"
              " (unchecked %d), stable %d (single bodies: %d)\n",
              amax, sp.roots.size(), sec, err, sp.det_residual, sp.unchecked, sp.stable, ref_stable);
  EXPECT_LT(amax, 1e-12);
  EXPECT_EQ(sp.roots.size(), 300u);
  EXPECT_LT(err, 1e-9);
  EXPECT_LT(sp.det_residual, 3e-9);  // measured 2.5e-10
  EXPECT_EQ(sp.stable, ref_stable);
}

// Near-massless shells (mass, A, C = 1e-9 of the fluid's) around spheroids of aspect c/a = 1/50 and 50
// (Greenhill: stable, c < a and c > 3a) and 2 (unstable): verdict and roots against the closed quadratic
// of test_spectrum's Greenhill test with the shell added.
TEST(Extreme, NearMasslessShellsAndAspect50) {
  const double w = 50, rho = 1000, L = 0.1;
  for (double ratio : {1.0 / 50, 2.0, 50.0}) {
    const rc::ModeTable t = spheroid_table(1.0, ratio);
    const double f = rho * std::pow(L, 5), mf = rho * L * L * L * t.volume;
    Body b; b.mass = 1e-9 * mf; b.A = 1e-9 * f * t.A_f; b.C = 1e-9 * f * t.C_f; b.com = 0; b.spin = w;
    b.table = spheroid_file(1.0, ratio); b.scale = L; b.density = rho; b.center = 0;
    const Spectrum sp = compute_spectrum(model_of(scene_text({b}, {}, 0.0)));
    ASSERT_TRUE(all_finite(sp));
    const double Af = f * t.A_f + b.A, Cf = f * t.C_f + b.C, E = f * t.E[0], l = w * t.lambda[0];
    const double qa = Af - E, qb = Af * (w - l) + Cf * w - E * w, qc = Cf * w * (w - l);
    const cd disc = std::sqrt(cd(qb * qb - 4 * qa * qc));
    const std::vector<cd> exact = {0.0, (-qb + disc) / (2 * qa), (-qb - disc) / (2 * qa)};
    const double err = root_set_distance(roots_of(sp), exact, spectral_radius(exact));
    const bool greenhill_stable = !(ratio > 1 && ratio < 3);
    std::printf("  c/a = %g, shell 1e-9 of the fluid: stable %d (Greenhill %d), margin %.3e, root error %.2e, det residual"
                " %.2e\n", ratio, sp.stable, greenhill_stable, sp.margin, err, sp.det_residual);
    EXPECT_EQ(sp.stable, greenhill_stable);
    EXPECT_LT(err, 1e-9);
    EXPECT_LT(sp.det_residual, 1e-9);  // measured 7.4e-11 (c/a = 50)
  }
}

// A shell of 1e-9 of a sphere's fluid (J_zh = 0: the shell alone carries M_eff) still works; at 1e-15
// M_eff = A_f + A_shell - E is rounding noise and the scene is refused with one line, not solved.
TEST(Extreme, NearMasslessShellAroundSphereIsSolvedOrRefused) {
  const double rho = 1000, L = 0.1, w = 50;
  const rc::ModeTable t = sphere_table(1.0);
  const double mf = rho * L * L * L * t.volume, Af = rho * std::pow(L, 5) * t.A_f;
  for (double ratio : {1e-9, 1e-15}) {
    Body b; b.mass = ratio * mf; b.A = ratio * Af; b.C = ratio * Af; b.com = 0; b.spin = w;
    b.table = sphere_file(1.0); b.scale = L; b.density = rho; b.center = 0;
    const std::string text = scene_text({b}, {}, 0.0);
    if (ratio > 1e-12) {
      const Spectrum sp = compute_spectrum(model_of(text));
      ASSERT_TRUE(all_finite(sp));
      // shell alone: A s^2 + C w s = 0 -> s = -C w / A = -w (the sphere's fluid is inert to the tilt)
      double far = 0;
      for (const auto& r : sp.roots) far = std::max(far, std::abs(r.sigma));
      std::printf("  sphere, shell %g of the fluid: roots up to %.10g rad/s (shell alone: %g), stable %d\n", ratio, far,
                  w, sp.stable);
      EXPECT_NEAR(far, w, 1e-4 * w);
      EXPECT_TRUE(sp.stable);
    } else {
      try {
        (void)model_of(text);
        ADD_FAILURE() << "shell " << ratio << " accepted";
      } catch (const SceneError& e) {
        std::printf("  sphere, shell %g: refused: %s\n", ratio, e.what());
        EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos);
      }
    }
  }
}
