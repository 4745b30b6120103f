// Batyr (2010) (three pendulums with fluid, joint friction, w = 0) and the energy: its derivation,
// conservation under exact propagation and decay with friction.
#include "energy.hpp"
#include "krein_gap.hpp"
#include "propagation.hpp"
#include "rom_test_util.hpp"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <random>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

namespace {
// Batyr (2010): three hanging pendulums (centres of mass and joints below O_k: com, next_joint < 0),
// cavities with ideal fluid, friction alpha_k in the joints, no spin.
std::vector<Body> batyr_bodies(bool with_fluid) {
  Body b1; b1.mass = 2; b1.A = 0.3; b1.C = 0.01; b1.com = -0.2; b1.next = -0.4;
  Body b2; b2.mass = 1.5; b2.A = 0.2; b2.C = 0.01; b2.com = -0.15; b2.next = -0.35;
  Body b3; b3.mass = 1; b3.A = 0.1; b3.C = 0.01; b3.com = -0.1;
  if (with_fluid) {
    b1.table = spheroid_file(1, 1.8); b1.scale = 0.06; b1.center = -0.2;
    b3.table = spheroid_file(1, 0.5); b3.scale = 0.05; b3.center = -0.12;
  }
  return {b1, b2, b3};
}
std::vector<cd> tilt_roots(const Spectrum& sp, int n_fluid, double tol) {
  std::vector<cd> r;
  int zeros = 0;
  for (const auto& x : sp.roots) {
    if (std::abs(x.sigma) <= tol) ++zeros;
    else r.push_back(x.sigma);
  }
  EXPECT_EQ(zeros, n_fluid) << "one root sigma = 0 per fluid mode at w = 0";
  return r;
}
// Batyr's operators restricted to the tilts: C = M_eff, A = D (43), B = K; property 3 (81) and (84).
struct Bounds { double re_min, abs_max, lhs84, rhs84; };
Bounds batyr_bounds(const ChainModel& m) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ge(m.D, m.M_eff);   // C^{-1/2} A C^{-1/2}
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> gb(m.K, m.M_eff);   // C^{-1/2} B C^{-1/2}
  const double amin = ge.eigenvalues().minCoeff(), bmax = gb.eigenvalues().maxCoeff();
  return {0.5 * amin, std::sqrt(bmax), amin, 2 * std::sqrt(bmax)};
}
}  // namespace

TEST(Batyr, TiltRootsDecayRespectTheoremSixAndProperty3) {
  std::vector<Body> bodies = batyr_bodies(true);
  const std::vector<Joint> joints = {{0, 0.02}, {0, 0.01}};
  const ChainModel m = model_of(scene_text(bodies, joints, 9.81, false, 0.03));
  const Spectrum sp = compute_spectrum(m);
  const auto tilts = tilt_roots(sp, m.n_modes(), sp.tolerance);
  ASSERT_EQ(tilts.size(), 6u);
  const Bounds bd = batyr_bounds(m);
  int oscillatory = 0;
  double min_decay = 1e300, worst81 = -1e300;
  for (cd s : tilts) {
    // Batyr (73): exp(-lambda t) = exp(i sigma t), lambda = -i sigma: Re lambda = Im sigma.
    const cd lam = cd(0, -1) * s;
    min_decay = std::min(min_decay, lam.real());
    if (std::abs(lam.imag()) > sp.tolerance) {
      ++oscillatory;
      worst81 = std::max({worst81, bd.re_min - lam.real(), std::abs(lam) - bd.abs_max});
    }
  }
  // Theorem 6's bound on the oscillatory roots is the tilts' count here (6): it holds for any spectrum of this chain,
  // so it is not asserted.
  std::printf("  smallest decay rate %.4e 1/s; %d oscillatory tilt roots; (81) worst violation %.2e (Re bound %.3e, "
              "|lambda| bound %.3e)\n", min_decay, oscillatory, worst81, bd.re_min, bd.abs_max);
  EXPECT_GT(min_decay, sp.tolerance);
  EXPECT_GT(oscillatory, 0);      // light friction: the pendulums do oscillate
  EXPECT_LE(worst81, 1e-9 * bd.abs_max);
  EXPECT_TRUE(sp.stable);

  // (84): with friction large enough no root is oscillatory.
  std::vector<Joint> strong = {{0, 60}, {0, 40}};
  const ChainModel ms = model_of(scene_text(bodies, strong, 9.81, false, 80));
  const Bounds bs = batyr_bounds(ms);
  ASSERT_GT(bs.lhs84, bs.rhs84) << "scene does not satisfy (84)";
  const Spectrum ss = compute_spectrum(ms);
  int osc = 0;
  double worst_re = 0;
  for (cd s : tilt_roots(ss, ms.n_modes(), ss.tolerance)) {
    worst_re = std::max(worst_re, std::abs(s.real()) / std::abs(s));
    if (std::abs(s.real()) > ss.tolerance) ++osc;
    EXPECT_GT(s.imag(), 0);
  }
  std::printf("  under (84) (%.3f > %.3f): %d oscillatory roots, largest |Re sigma|/|sigma| %.1e\n", bs.lhs84,
              bs.rhs84, osc, worst_re);
  EXPECT_EQ(osc, 0);
}

// Batyr (2010) Theorem 2 (Zhukovsky): at w = 0 the fluid acts as a rigid body with the Zhukovsky inertia.
TEST(Batyr, ZhukovskyEquivalenceAtZeroSpin) {
  const std::vector<Joint> joints = {{1.0, 0.02}, {0.5, 0.01}};
  std::vector<Body> fluid = batyr_bodies(true), rigid = batyr_bodies(false);
  for (int k : {0, 2}) {
    const rc::ModeTable t = k == 0 ? spheroid_table(1, 1.8) : spheroid_table(1, 0.5);
    const Body& b = fluid[k];
    const double L = b.scale, mf = b.density * L * L * L * t.volume, Jzh = b.density * std::pow(L, 5) * t.J_zh;
    Body& r = rigid[k];
    r.com = (b.mass * b.com + mf * b.center) / (b.mass + mf);
    r.mass = b.mass + mf;
    r.A = b.A + Jzh + mf * b.center * b.center;
  }
  const Spectrum sf = compute_spectrum(model_of(scene_text(fluid, joints, 9.81, false, 0.03)));
  const Spectrum sr = compute_spectrum(model_of(scene_text(rigid, joints, 9.81, false, 0.03)));
  const auto tf = tilt_roots(sf, 2, sf.tolerance);
  const double err = root_set_distance(tf, roots_of(sr), spectral_radius(roots_of(sr)));
  std::printf("  fluid chain vs Zhukovsky rigid chain: relative distance %.2e\n", err);
  EXPECT_LT(err, 1e-11);
}

namespace {
std::string spinning_text(double friction, const std::string& extra = "") {
  Body b1; b1.mass = 2; b1.A = 0.05; b1.C = 0.08; b1.com = 0.05; b1.next = 0.15; b1.spin = 200;
  b1.table = spheroid_file(1, 0.6); b1.scale = 0.04; b1.center = 0.05;
  Body b2; b2.mass = 1; b2.A = 0.02; b2.C = 0.035; b2.com = 0.04; b2.spin = 150;
  b2.table = spheroid_file(1, 0.7); b2.scale = 0.03; b2.center = 0.04;
  return scene_text({b1, b2}, {{5.0, friction}}, 9.81, false, friction, extra);
}
ChainModel spinning_chain(double friction) { return model_of(spinning_text(friction)); }
std::string run_section(double t_end, double step, const std::string& method) {
  return "[initial]\ntilt = [[0.01, 0.0], [0.0, -0.005]]\nrate = [[0.0, 0.1], [0.2, 0.0]]\n[run]\nt_end = " +
         num(t_end) + "\noutput_step = " + num(step) + "\nmethod = \"" + method + "\"\ntolerance = 1e-11\n";
}
}  // namespace

// The energy of energy.hpp: dH/dt = -u'^H D u' along the first-order system, at random states of a
// spinning chain with fluid, elastic joints and friction (checks the derivation in docs/rom.md).
TEST(Energy, DerivativeEqualsMinusFrictionPower) {
  const ChainModel m = spinning_chain(0.01);
  const FirstOrderSystem f = build_first_order(m);
  std::mt19937 gen(3);
  std::normal_distribution<double> N;
  const Eigen::VectorXd c = fluid_weights(m);
  double worst = 0;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXcd y(f.dim());
    for (int i = 0; i < f.dim(); ++i) y[i] = cd(N(gen), N(gen));
    const Eigen::VectorXcd dy = f.B * y;
    Eigen::VectorXcd u, v, w, du, dv, dw;
    f.from_state(m, y, u, v, w);
    f.from_state(m, dy, du, dv, dw);
    const Eigen::MatrixXcd Me = m.M_eff.cast<cd>(), K = m.K.cast<cd>();
    double dH = (v.adjoint() * Me * dv)(0, 0).real() + (u.adjoint() * K * du)(0, 0).real();
    double size = std::abs((v.adjoint() * Me * dv)(0, 0)) + std::abs((u.adjoint() * K * du)(0, 0));
    for (int l = 0; l < m.n_modes(); ++l) {
      dH += c[l] * (std::conj(w[l]) * dw[l]).real();
      size += std::abs(c[l] * std::conj(w[l]) * dw[l]);
    }
    worst = std::max(worst, std::abs(dH - dissipation(m, v)) / size);
  }
  std::printf("  |dH/dt + u'^H D u'| / size = %.2e\n", worst);
  EXPECT_LT(worst, 1e-13);
}

// Exact propagation keeps the energy to 1e-12 over 1e4 periods (no friction); gauss and rk45
// agree with it over a shorter span; with friction H never increases.
TEST(Energy, ExactPropagationConservesEnergyOver1e4Periods) {
  const ChainModel m = spinning_chain(0);
  const Spectrum sp = compute_spectrum(m);
  ASSERT_TRUE(sp.stable) << "test scene should be gyroscopically stable";
  double slowest = 1e300;
  for (const auto& r : sp.roots) if (std::abs(r.sigma) > 1e-6) slowest = std::min(slowest, std::abs(r.sigma));
  const double t_end = 1e4 * 2 * M_PI / slowest;  // 1e4 periods of the slowest root
  const Scene s = parse_scene_text(spinning_text(0, run_section(t_end, t_end / 4000, "exact")), test_dir(), "x");
  const History h = propagate(build_model(s), s);
  std::printf("  %s: %.3g s = 1e4 periods, relative energy drift %.2e\n", h.method_used.c_str(), t_end,
              h.max_energy_drift);
  EXPECT_LT(h.max_energy_drift, 1e-12);
  EXPECT_GT(std::abs(h.u(h.t.size() - 1, 0)), 0);

  // gauss and rk45 against exact over 200 periods of the fastest root
  double fastest = 0;
  for (const auto& r : sp.roots) fastest = std::max(fastest, std::abs(r.sigma));
  const double t2 = 200 * 2 * M_PI / fastest;
  const Scene se = parse_scene_text(spinning_text(0, run_section(t2, t2 / 200, "exact")), test_dir(), "x");
  const History he = propagate(build_model(se), se);
  for (const std::string meth : {"gauss", "rk45"}) {
    const Scene sg = parse_scene_text(spinning_text(0, run_section(t2, t2 / 200, meth)), test_dir(), "x");
    const History hg = propagate(build_model(sg), sg);
    const double diff = (hg.u - he.u).cwiseAbs().maxCoeff() / he.u.cwiseAbs().maxCoeff();
    std::printf("  %s vs exact: max |u diff| / max |u| = %.2e, energy drift %.2e\n", hg.method_used.c_str(), diff,
                hg.max_energy_drift);
    EXPECT_LT(diff, 1e-6);
  }
}

TEST(Energy, FrictionNeverIncreasesTheEnergy) {
  const Scene s = parse_scene_text(spinning_text(0.002, run_section(5.0, 0.001, "exact")), test_dir(), "x");
  const ChainModel m = build_model(s);
  const History h = propagate(m, s);
  std::printf("  H(0) = %.6e, H(end) = %.6e, largest relative increase per step %.2e\n", h.H.front(), h.H.back(),
              h.max_energy_drift);
  EXPECT_LT(h.max_energy_drift, 1e-13);
  EXPECT_LT(h.H.back(), h.H.front());
}

// docs/physics.md §3: at w0 = 0 only sum E = A_f - J_zh matters. One kept mode + static correction must give the
// tilt roots of all four modes of a synthetic table (written in test_scene.cpp's table test).
TEST(Energy, StaticCorrectionRestoresZhukovskyInertiaAtZeroSpin) {
  const rc::ModeTable t = four_mode_table();
  write_table(t, test_dir() / "four_modes_b.h5");
  std::vector<Body> bodies = batyr_bodies(false);
  bodies[0].table = "four_modes_b.h5"; bodies[0].scale = 0.06; bodies[0].center = -0.2;
  const std::vector<Joint> joints = {{0, 0.02}, {0, 0.01}};
  const Spectrum all = compute_spectrum(model_of(scene_text(bodies, joints, 9.81, false, 0.03)));
  bodies[0].modes = 1; bodies[0].static_correction = true;
  const Spectrum one = compute_spectrum(model_of(scene_text(bodies, joints, 9.81, false, 0.03)));
  bodies[0].static_correction = false;
  const Spectrum bare = compute_spectrum(model_of(scene_text(bodies, joints, 9.81, false, 0.03)));
  const auto ta = tilt_roots(all, 4, all.tolerance), t1 = tilt_roots(one, 1, one.tolerance);
  const auto tb = tilt_roots(bare, 1, bare.tolerance);
  const double R = spectral_radius(ta);
  const double err = root_set_distance(t1, ta, R), err_bare = root_set_distance(tb, ta, R);
  std::printf("  1 mode + static correction vs 4 modes: %.2e; without the correction: %.2e\n", err, err_bare);
  EXPECT_LT(err, 1e-12);
  EXPECT_GT(err_bare, 1e-6);  // the correction matters
}

// Batyr's Property 7 on his three pendulums with fluid at w = 0: without friction the tilts' spectrum is purely
// imaginary in his λ (real in our σ), σ = ±√μ_k with μ_k the eigenvalues of C11⁻¹B1 (Batyr (87) restricted to the
// tilts). At w = 0 the fluid acts as Zhukovsky's rigid body (Batyr Theorem 2), so C11 and B1 are those of a planar
// chain of rigid pendulums, built here by hand from the bodies, the cavities' volume and J_zh alone (not from the
// model): with absolute tilts θ_k, joint k + 1 at ℓ_k = next_joint_k along body k and A_k about joint k,
//   a_k = m_k c_k + ℓ_k Σ_{i>k} m_i,   M_kk = A_k + ℓ_k² Σ_{i>k} m_i,   M_kj = ℓ_k a_j (j > k),   K = −g diag(a_k),
// the kinetic and potential energies of the hanging chain to second order (Kononov's (26), docs/physics.md §3, at
// ω = 0 with no fluid: built here from those formulas, not by the model). Property 11 (the root vectors form a
// basis): the tilt roots are simple, so the companion matrix is diagonalisable there.
namespace {
struct PlanarChain { Eigen::MatrixXd M, K; };
PlanarChain zhukovsky_pendulums(std::vector<Body> bodies, double g) {
  for (Body& b : bodies) {
    if (b.table.empty()) continue;
    const rc::ModeTable t = rc::read_mode_table(test_dir() / b.table);
    const double L = b.scale, mf = b.density * L * L * L * t.volume, Jzh = b.density * std::pow(L, 5) * t.J_zh;
    b.A += Jzh + mf * b.center * b.center;
    b.com = (b.mass * b.com + mf * b.center) / (b.mass + mf);
    b.mass += mf;
  }
  const int n = static_cast<int>(bodies.size());
  std::vector<double> below(n, 0.0), a(n);  // below[k]: the mass hanging from joint k + 1
  for (int k = n - 2; k >= 0; --k) below[k] = below[k + 1] + bodies[k + 1].mass;
  for (int k = 0; k < n; ++k) a[k] = bodies[k].mass * bodies[k].com + bodies[k].next * below[k];
  PlanarChain c{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (int k = 0; k < n; ++k) {
    c.M(k, k) = bodies[k].A + bodies[k].next * bodies[k].next * below[k];
    for (int j = k + 1; j < n; ++j) c.M(k, j) = c.M(j, k) = bodies[k].next * a[j];
    c.K(k, k) = -g * a[k];
  }
  return c;
}
}  // namespace

TEST(Batyr, PropertySevenWithoutFriction) {
  const ChainModel m = model_of(scene_text(batyr_bodies(true), {{0, 0}, {0, 0}}, 9.81, false, 0));
  const Spectrum sp = compute_spectrum(m);
  const auto tilts = tilt_roots(sp, m.n_modes(), sp.tolerance);
  ASSERT_EQ(tilts.size(), 6u);
  const PlanarChain hand = zhukovsky_pendulums(batyr_bodies(true), 9.81);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ge(hand.K, hand.M);
  double worst = 0, imag = 0, gap = 1e300;
  for (const cd s : tilts) {
    double nearest = 1e300;
    for (Eigen::Index k = 0; k < ge.eigenvalues().size(); ++k)
      nearest = std::min(nearest, std::abs(std::abs(s.real()) - std::sqrt(ge.eigenvalues()[k])));
    worst = std::max(worst, nearest);
    imag = std::max(imag, std::abs(s.imag()));
    for (const cd t : tilts)
      if (t != s) gap = std::min(gap, std::abs(t - s));
  }
  std::printf("  tilt roots: largest |Im sigma| %.1e; against (87) on the hand-built pendulums %.1e rad/s; closest pair "
              "%.3g rad/s apart (simple roots)\n", imag, worst, gap);
  EXPECT_LT(imag, sp.tolerance);
  EXPECT_LT(worst, 1e-9 * std::sqrt(ge.eigenvalues().maxCoeff()));
  EXPECT_GT(gap, 1e-3);
  EXPECT_TRUE(sp.stable);
}

// Batyr's Lemma 1: the gravity operator B of (44) is non-negative, diagonal, with b_kk = m_k l_k + (m_{k+1} + …) h_k
// for his hanging chain (the liquid frozen at its centre; l_k, h_k the depths of body k's centre of mass and next joint
// below joint k). Its kernel (45) is the three axial directions, which (26) leaves to the spins' own block
// (axial_rotation.hpp): on the tilts B is positive definite. The model's K against (44) built by hand, and the same
// chain standing on its joints (every position mirrored) must lose it.
TEST(Batyr, LemmaOneGravityIsNonNegativeForTheHangingChain) {
  const std::vector<Body> hanging = batyr_bodies(true);
  const ChainModel m = model_of(scene_text(hanging, {{0, 0}, {0, 0}}, 9.81, false, 0));
  const PlanarChain hand = zhukovsky_pendulums(hanging, 9.81);
  const double against_44 = (m.K - hand.K).norm() / hand.K.norm();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> hang(m.K);
  std::vector<Body> standing = hanging;
  for (Body& b : standing) {
    b.com = -b.com;
    b.next = -b.next;
    b.center = -b.center;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> stand(model_of(scene_text(standing, {{0, 0}, {0, 0}}, 9.81, false, 0)).K);
  std::printf("  K against (44) by hand %.1e; hanging: eigenvalues of B %.4g … %.4g N m (kernel on the tilts: none); "
              "standing: %.4g … %.4g\n", against_44, hang.eigenvalues().minCoeff(), hang.eigenvalues().maxCoeff(),
              stand.eigenvalues().minCoeff(), stand.eigenvalues().maxCoeff());
  EXPECT_LT(against_44, 1e-14);
  EXPECT_GT(hang.eigenvalues().minCoeff(), 1e-3 * hang.eigenvalues().maxCoeff());
  EXPECT_LT(stand.eigenvalues().maxCoeff(), 0.0);
}

// Batyr's Property 2: with friction A (43) the roots λ (e^{−λt}; ours e^{iσt}, λ = −iσ) of (75), λ²C − λA + B = 0, are
// on their eigenvectors u the roots of (79), λ± = ((Au, u) ± √((Au, u)² − 4 (Cu, u)(Bu, u))) / (2 (Cu, u)), and
// Re λ > 0 (80). C, A and B built by hand (the hanging Zhukovsky pendulums and (43)'s tridiagonal friction), the roots
// the model's: each must make the hand-built pencil singular, and (79) on its null vector must return it. With the
// support's friction left out of the hand-built A the pencil is no longer singular there.
TEST(Batyr, PropertyTwoRootsAreTheirEigenvectorsQuotients) {
  const std::vector<Body> bodies = batyr_bodies(true);
  const double alpha[3] = {0.03, 0.02, 0.01};  // the support, joint 1, joint 2
  const ChainModel m = model_of(scene_text(bodies, {{0, alpha[1]}, {0, alpha[2]}}, 9.81, false, alpha[0]));
  const Spectrum sp = compute_spectrum(m);
  const auto tilts = tilt_roots(sp, m.n_modes(), sp.tolerance);
  ASSERT_EQ(tilts.size(), 6u);
  const PlanarChain hand = zhukovsky_pendulums(bodies, 9.81);
  const auto friction = [&](bool with_support) {  // Batyr (43)
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3, 3);
    for (int k = 0; k < 3; ++k) A(k, k) = (k == 0 && !with_support ? 0.0 : alpha[k]) + (k < 2 ? alpha[k + 1] : 0.0);
    for (int k = 0; k < 2; ++k) A(k, k + 1) = A(k + 1, k) = -alpha[k + 1];
    return A;
  };
  // Per root: the hand-built pencil's smallest singular value against its norm, and (79) on its null vector.
  const auto measure = [&](const Eigen::MatrixXd& A, cd lambda, double& singular, double& quotient) {
    const Eigen::MatrixXcd Q = lambda * lambda * hand.M.cast<cd>() - lambda * A.cast<cd>() + hand.K.cast<cd>();
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(Q, Eigen::ComputeFullV);
    singular = svd.singularValues()(2) / svd.singularValues()(0);
    const Eigen::VectorXcd u = svd.matrixV().col(2);
    const double c = u.dot(hand.M.cast<cd>() * u).real(), a = u.dot(A.cast<cd>() * u).real(),
                 b = u.dot(hand.K.cast<cd>() * u).real();
    const cd root = std::sqrt(cd(a * a - 4 * c * b));
    quotient = std::min(std::abs((a + root) / (2 * c) - lambda), std::abs((a - root) / (2 * c) - lambda)) / std::abs(lambda);
  };
  double worst_singular = 0, worst_quotient = 0, min_re = 1e300, wrong_singular = 1e300;
  for (const cd s : tilts) {
    const cd lambda = cd(0, -1) * s;
    double singular = 0, quotient = 0;
    measure(friction(true), lambda, singular, quotient);
    worst_singular = std::max(worst_singular, singular);
    worst_quotient = std::max(worst_quotient, quotient);
    min_re = std::min(min_re, lambda.real());
    measure(friction(false), lambda, singular, quotient);
    wrong_singular = std::min(wrong_singular, singular);
  }
  std::printf("  (75) by hand at the model's 6 tilt roots: smallest singular value %.1e of the largest; (79) on the "
              "null vectors returns the root to %.1e; smallest Re lambda %.4e 1/s (80); without the support's friction "
              "the pencil's smallest singular value is %.1e\n", worst_singular, worst_quotient, min_re, wrong_singular);
  EXPECT_LT(worst_singular, 1e-12);
  EXPECT_LT(worst_quotient, 1e-10);
  EXPECT_GT(min_re, 0.0);
  EXPECT_GT(wrong_singular, 1e-6);  // measured 1.7e-4: the friction is light, yet 1e11 times the right pencil's
}

// Batyr's Theorem 6 (second part) and Property 11 on one transverse plane of his three pendulums (at ω = 0 the two planes
// are alike and the axial block is apart, axial_rotation.hpp): where the friction is strong enough for (84),
// λ_min(C^{-1/2} A C^{-1/2}) > 2 λ_max(C^{-1/2} B C^{-1/2})^{1/2}, every root is real and positive and the eigenvectors of
// (90)–(92)'s operator 𝒜 = [[C^{-1/2}AC^{-1/2}, i C^{-1/2}B^{1/2}], [i B^{1/2}C^{-1/2}, 0]], self-adjoint in the metric
// J = diag(I, −I) (98), are a J-orthogonal basis. 𝒜 built by hand; the product's part is its eigenvalues against the
// model's roots (and the model's roots all real and positive); the basis and its J-orthogonality check Batyr's statement
// on his own operator, as the issue of his last results asked.
TEST(Batyr, TheoremSixStrongFrictionGivesRealRootsAndAJOrthogonalBasis) {
  const std::vector<Body> bodies = batyr_bodies(true);
  const PlanarChain hand = zhukovsky_pendulums(bodies, 9.81);
  const auto friction = [](const double (&alpha)[3]) {  // Batyr (43)
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3, 3);
    for (int k = 0; k < 3; ++k) A(k, k) = alpha[k] + (k < 2 ? alpha[k + 1] : 0.0);
    for (int k = 0; k < 2; ++k) A(k, k + 1) = A(k + 1, k) = -alpha[k + 1];
    return A;
  };
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> Ch(hand.M);
  const Eigen::MatrixXd Cm = Ch.operatorInverseSqrt(), Bh = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hand.K).operatorSqrt();
  const double light[3] = {0.03, 0.02, 0.01};
  const double amin = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Cm * friction(light) * Cm).eigenvalues().minCoeff();
  const double bmax = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Cm * hand.K * Cm).eigenvalues().maxCoeff();
  const double scale = 1.5 * 2 * std::sqrt(bmax) / amin;  // (84) with a margin of 1.5
  const double alpha[3] = {scale * light[0], scale * light[1], scale * light[2]};
  const Eigen::MatrixXd A = friction(alpha);
  const ChainModel m = model_of(scene_text(bodies, {{0, alpha[1]}, {0, alpha[2]}}, 9.81, false, alpha[0]));
  const Spectrum sp = compute_spectrum(m);
  const auto tilts = tilt_roots(sp, m.n_modes(), sp.tolerance);
  ASSERT_EQ(tilts.size(), 6u);
  Eigen::MatrixXcd op = Eigen::MatrixXcd::Zero(6, 6);  // (92)
  op.topLeftCorner(3, 3) = (Cm * A * Cm).cast<cd>();
  op.topRightCorner(3, 3) = cd(0, 1) * (Cm * Bh).cast<cd>();
  op.bottomLeftCorner(3, 3) = cd(0, 1) * (Bh * Cm).cast<cd>();
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(op);
  Eigen::VectorXcd Jd(6);
  Jd << 1, 1, 1, -1, -1, -1;
  const Eigen::MatrixXcd& V = es.eigenvectors();
  const Eigen::MatrixXcd gram = V.adjoint() * Jd.asDiagonal() * V;  // [v_i, v_j] (96)
  double off = 0, diag_min = 1e300, worst_root = 0, max_imag = 0, min_lambda = 1e300;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j)
      if (i != j) off = std::max(off, std::abs(gram(i, j)) / std::sqrt(std::abs(gram(i, i) * gram(j, j))));
    diag_min = std::min(diag_min, std::abs(gram(i, i)) / V.col(i).squaredNorm());
    max_imag = std::max(max_imag, std::abs(es.eigenvalues()[i].imag()));
    min_lambda = std::min(min_lambda, es.eigenvalues()[i].real());
  }
  // Each of the model's tilt roots (λ = −iσ) against the nearest eigenvalue of (92); at ω = 0 each appears in both
  // planes, and the model's complex tilts carry the plane once.
  for (const cd s : tilts) {
    const cd lambda = cd(0, -1) * s;
    double nearest = 1e300;
    for (int i = 0; i < 6; ++i) nearest = std::min(nearest, std::abs(es.eigenvalues()[i] - lambda));
    worst_root = std::max(worst_root, nearest / std::abs(lambda));
    max_imag = std::max(max_imag, std::abs(lambda.imag()));
  }
  const Eigen::JacobiSVD<Eigen::MatrixXcd> basis(V);
  const double condition = basis.singularValues()(0) / basis.singularValues()(5);
  std::printf("  friction x%.3g for (84): the model's tilt roots are (92)'s eigenvalues to %.1e, all real (|Im| <= "
              "%.1e) and positive (smallest %.4g 1/s); (92)'s eigenvectors J-orthogonal to %.1e, |[v, v]| >= %.3g of "
              "|v|^2; a basis of condition %.3g (Property 11)\n", scale, worst_root, max_imag, min_lambda, off, diag_min,
              condition);
  EXPECT_LT(worst_root, 1e-10);
  EXPECT_LT(max_imag, 1e-9 * std::sqrt(bmax));
  EXPECT_GT(min_lambda, 0.0);
  EXPECT_LT(off, 1e-10);
  EXPECT_GT(diag_min, 1e-3);
  EXPECT_LT(condition, 1e6);
}

// Batyr's indefinite metric (90)–(98) against krein_gap's signature (krein_gap.hpp) where both apply: the undamped
// chain at ω = 0. They answer different questions. Batyr's J makes the damped operator 𝒜 self-adjoint, and its definite
// vectors are the real λ (overdamped) roots. Without friction every root is an oscillation, λ = −iσ non-real, so every
// eigenvector of 𝒜 is J-neutral ([v, v] = 0). krein_gap's signature, sign vᵀ Φ'(σ) v, reads the real-σ roots of the
// undamped chain. At ω = 0, Φ(σ) = M − K/σ² (characteristic.hpp, with the liquid's part of M), Φ'(σ) = 2K/σ³, and K > 0
// on the hanging chain (Lemma 1): the signature is sign σ. The two roots ±σ of one pendulum mode have opposite signs
// and meet only at σ = 0. The product's part is krein_signature; the J-neutrality checks Batyr's construction itself.
TEST(Batyr, IndefiniteMetricAndKreinSignatureOfTheUndampedChain) {
  const std::vector<Body> bodies = batyr_bodies(true);
  const PlanarChain hand = zhukovsky_pendulums(bodies, 9.81);
  const Eigen::MatrixXd Cm = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hand.M).operatorInverseSqrt();
  const Eigen::MatrixXd Bh = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hand.K).operatorSqrt();
  Eigen::MatrixXcd op = Eigen::MatrixXcd::Zero(6, 6);  // (92) with A = 0
  op.topRightCorner(3, 3) = cd(0, 1) * (Cm * Bh).cast<cd>();
  op.bottomLeftCorner(3, 3) = cd(0, 1) * (Bh * Cm).cast<cd>();
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(op);
  double neutral = 0;
  for (int i = 0; i < 6; ++i) {
    const Eigen::VectorXcd& v = es.eigenvectors().col(i);
    neutral = std::max(neutral, std::abs(v.head(3).squaredNorm() - v.tail(3).squaredNorm()) / v.squaredNorm());
  }
  const ChainModel m = model_of(scene_text(bodies, {{0, 0}, {0, 0}}, 9.81, false, 0));
  const auto tilts = tilt_roots(compute_spectrum(m), m.n_modes(), 1e-9);
  int agree = 0;
  for (const cd s : tilts) agree += krein_signature(m, s.real()) == (s.real() > 0 ? 1 : -1);
  std::printf("  A = 0: |[v, v]| <= %.1e of |v|^2 for every eigenvector of (92) (all J-neutral); krein_signature = "
              "sign sigma at %d of %zu tilt roots\n", neutral, agree, tilts.size());
  EXPECT_LT(neutral, 1e-12);
  EXPECT_EQ(agree, static_cast<int>(tilts.size()));
}
