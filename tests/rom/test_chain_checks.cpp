// Checks Kononov's and Batyr's papers give for free: decoupling (23)-(24), free chain (30)/(32), factorisations (33)/(34).
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

namespace {
std::vector<cd> single_body_roots(const Body& b, double g) {
  return roots_of(compute_spectrum(model_of(scene_text({b}, {}, g))));
}
double fluid_mass(const Body& b, double volume) { return b.density * std::pow(b.scale, 3) * volume; }
}  // namespace

// a_2 = a_3 = 0 (O_k at the centre of mass of the "enlarged" body k): (22) splits into (23) for
// body 1 (fixed top with gravity) and (24) for bodies 2, 3 (free bodies about their centre of mass).
TEST(ChainChecks, DecouplingIntoEquations23And24) {
  const double g = 9.81, s1 = 0.3, s2 = 0.25;
  const rc::ModeTable t1 = spheroid_table(1, 0.7), t3 = spheroid_table(1, 1.4);
  Body b1; b1.mass = 3; b1.A = 0.2; b1.C = 0.25; b1.com = 0.1; b1.next = s1; b1.spin = 60;
  b1.table = spheroid_file(1, 0.7); b1.scale = 0.06; b1.center = 0.08;
  Body b3; b3.mass = 1; b3.A = 0.03; b3.C = 0.04; b3.com = 0; b3.spin = 90;
  b3.table = spheroid_file(1, 1.4); b3.scale = 0.03; b3.center = 0;  // c_3 = 0: a_3 = 0
  const double m3 = b3.mass + fluid_mass(b3, t3.volume);
  Body b2; b2.mass = 2; b2.A = 0.06; b2.C = 0.05; b2.next = s2; b2.spin = 75;
  b2.com = -s2 * m3 / b2.mass;  // a_2 = m_2 c_2 + s_2 m_3 = 0
  const ChainModel m = model_of(scene_text({b1, b2, b3}, {{}, {}}, g));
  std::printf("  a = (%g, %.1e, %.1e)\n", m.a[0], m.a[1], m.a[2]);
  const std::vector<cd> chain = roots_of(compute_spectrum(m));

  // (23): body 1 alone with A'_1 = A_1 + s_1^2 (m_2 + m_3) and a_1 = m_1 c_1 + s_1 (m_2 + m_3).
  const double mf1 = fluid_mass(b1, t1.volume), tail = b2.mass + m3;
  Body r1 = b1;
  r1.A = b1.A + s1 * s1 * tail;
  r1.com = (b1.mass * b1.com + mf1 * b1.center + s1 * tail - mf1 * b1.center) / b1.mass;
  // (24): body 2 with A'_2 = A_2 + s_2^2 m_3, no gravity moment; body 3 as it is.
  Body r2 = b2; r2.A = b2.A + s2 * s2 * m3; r2.com = 0;
  std::vector<cd> ref = single_body_roots(r1, g), x2 = single_body_roots(r2, g), x3 = single_body_roots(b3, g);
  ref.insert(ref.end(), x2.begin(), x2.end());
  ref.insert(ref.end(), x3.begin(), x3.end());
  const double err = root_set_distance(chain, ref, spectral_radius(ref));
  std::printf("  chain roots vs (23)-(24): relative distance %.2e (%zu roots)\n", err, chain.size());
  EXPECT_LT(err, 1e-10);
}

// Free chain: the matrix derived in docs/free-chain.md against Kononov (30) (n = 3) and (32) (n = 2),
// whose A_k are about the centres of mass and whose c_1 is C_1 -> O_2.
TEST(ChainChecks, FreeChainMatrixMatchesKononov30And32) {
  Body b1; b1.mass = 3; b1.A = 0.2; b1.com = 0.11; b1.next = 0.32;
  Body b2; b2.mass = 1.7; b2.A = 0.07; b2.com = 0.09; b2.next = 0.27;
  Body b3; b3.mass = 0.9; b3.A = 0.03; b3.com = 0.05;
  const ChainModel m3 = model_of(scene_text({b1, b2, b3}, {{}, {}}, 9.81, true));
  const double m1 = 3, m2 = 1.7, mm3 = 0.9, m = m1 + m2 + mm3;
  const double c1 = 0.32 - 0.11, c2 = 0.09, s2 = 0.27, c3 = 0.05;  // Kononov's c_1 = C_1 O_2
  const double Ac1 = 0.2 - m1 * 0.11 * 0.11, Ac2 = 0.07 - m2 * c2 * c2, Ac3 = 0.03 - mm3 * c3 * c3;
  Eigen::Matrix3d seed;
  seed(0, 0) = Ac1 + m1 * (m2 + mm3) / m * c1 * c1;
  seed(1, 1) = Ac2 + (m2 * (m1 + mm3) * c2 * c2 - 2 * m2 * mm3 * c2 * s2 + mm3 * (m1 + m2) * s2 * s2) / m;
  seed(2, 2) = Ac3 + mm3 * (m1 + m2) / m * c3 * c3;
  seed(0, 1) = seed(1, 0) = m1 * c1 / m * (m2 * c2 + mm3 * s2);            // mu_1
  seed(0, 2) = seed(2, 0) = m1 * mm3 / m * c1 * c3;                        // mu_2
  seed(1, 2) = seed(2, 1) = mm3 * c3 / m * (m1 * s2 + (s2 - c2) * m2);     // mu_3
  const double e3 = (m3.M - seed).norm() / seed.norm();
  const ChainModel m2c = model_of(scene_text({b1, b2}, {{}}, 9.81, true));
  const double mt = m1 + m2, c2b = 0.09;
  Eigen::Matrix2d seed2;
  seed2(0, 0) = Ac1 + m1 * m2 / mt * c1 * c1;
  seed2(1, 1) = (0.07 - m2 * c2b * c2b) + m2 * m1 / mt * c2b * c2b;
  seed2(0, 1) = seed2(1, 0) = m1 * c1 / mt * m2 * c2b;
  const double e2 = (m2c.M - seed2).norm() / seed2.norm();
  std::printf("  |M - (30)|/|(30)| = %.2e, |M - (32)|/|(32)| = %.2e\n", e3, e2);
  EXPECT_LT(e3, 1e-14);
  EXPECT_LT(e2, 1e-14);
}

// Identical free bodies (c_k = c, s_k = 2c), equal spins, kappa = 0: (30) factors as (33),
// (F~ - 2/3)(F~ - 1/3)(F~ + 7/3) = 0, and (32) as (34), (F~ - 1/2)(F~ + 1/2) = 0, i.e. the roots are
// those of one body about its centre of mass with A^c + t m c^2, t in {0, 1/3, 3} (n = 3), {0, 1} (n = 2).
TEST(ChainChecks, IdenticalFreeBodiesFactorAs33And34) {
  const double c = 0.1, w = 70;
  const rc::ModeTable tab = spheroid_table(1, 0.8);
  Body b; b.mass = 2; b.C = 0.06; b.com = c; b.next = 2 * c; b.spin = w;
  b.table = spheroid_file(1, 0.8); b.scale = 0.05; b.center = c;
  const double Ac_shell = 0.03;
  b.A = Ac_shell + b.mass * c * c;  // about O_k
  const double mtot = b.mass + fluid_mass(b, tab.volume);
  for (int n : {3, 2}) {
    std::vector<Body> chain(n, b);
    const std::vector<cd> r = roots_of(compute_spectrum(model_of(scene_text(chain, std::vector<Joint>(n - 1), 0, true))));
    const std::vector<double> ts = n == 3 ? std::vector<double>{0, 1.0 / 3, 3} : std::vector<double>{0, 1};
    std::vector<cd> ref;
    for (double t : ts) {
      Body one = b; one.com = 0; one.center = 0; one.A = Ac_shell + t * mtot * c * c;
      const auto x = single_body_roots(one, 0);
      ref.insert(ref.end(), x.begin(), x.end());
    }
    const double err = root_set_distance(r, ref, spectral_radius(ref));
    std::printf("  n = %d: free-chain roots vs (%s): relative distance %.2e\n", n, n == 3 ? "33" : "34", err);
    EXPECT_LT(err, 1e-10);
  }
}

// Kononov (1999) (27)-(28): n identical Lagrange gyroscopes (c_k = c, s_k = 2c, m_k = m, central inertia A^c), a free
// chain with elastic joints, for general n. Kononov's coefficients, built here from its formulas:
//   A'_k = A^c + mu m c [(2n - 2k + 1)(2k - 1) - n],  a_k = (2n - 2k + 1) m c,  mu = c/n,
//   mu_ij = mu (2i - 1) a_j  (i < j; Kononov prints a_i, but its equations (27) carry mu a_k (2i - 1) for i < k),
// against the model's inertia matrix; then the roots of sigma^2 M' u + sigma C w u - K_el u = 0 (the quadratic
// eigenproblem of (27) without fluid, K_el the joints' Laplacian with kappa_k^2), by its companion matrix, against
// chain-rom's spectrum, and det (28) at each root.
TEST(ChainChecks, IdenticalGyroscopesKononov27And28GeneralN) {
  const double m = 1.3, c = 0.07, Ac = 0.011, C = 0.017, w = 120;
  for (int n : {4, 7, 10}) {
    Body b; b.mass = m; b.A = Ac + m * c * c; b.C = C; b.com = c; b.next = 2 * c; b.spin = w;
    std::vector<Joint> joints(n - 1);
    for (int k = 0; k + 1 < n; ++k) joints[k].stiffness = 50.0 * (1 + 0.3 * k);  // kappa_k^2, all different
    const ChainModel model = model_of(scene_text(std::vector<Body>(n, b), joints, 0, true));
    const double mu = c / n;
    Eigen::MatrixXd seed(n, n), Kel = Eigen::MatrixXd::Zero(n, n);
    for (int k = 1; k <= n; ++k) {
      seed(k - 1, k - 1) = Ac + mu * m * c * ((2.0 * n - 2 * k + 1) * (2.0 * k - 1) - n);
      for (int j = k + 1; j <= n; ++j)
        seed(k - 1, j - 1) = seed(j - 1, k - 1) = mu * (2.0 * k - 1) * (2.0 * n - 2 * j + 1) * m * c;
    }
    for (int k = 0; k + 1 < n; ++k) {
      const double kap = joints[k].stiffness;
      Kel(k, k) += kap; Kel(k + 1, k + 1) += kap; Kel(k, k + 1) -= kap; Kel(k + 1, k) -= kap;
    }
    const double eM = (model.M - seed).norm() / seed.norm();
    // Companion form of sigma^2 M' u + sigma G u - K_el u = 0 (G = C w I): [u; sigma u] eigenvector.
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    const Eigen::MatrixXd Mi = seed.inverse();
    Z.topRightCorner(n, n).setIdentity();
    Z.bottomLeftCorner(n, n) = Mi * Kel;
    Z.bottomRightCorner(n, n) = -Mi * (C * w);
    Eigen::EigenSolver<Eigen::MatrixXd> es(Z, false);
    std::vector<cd> ref(es.eigenvalues().data(), es.eigenvalues().data() + 2 * n);
    const std::vector<cd> got = roots_of(compute_spectrum(model));
    double radius = 0;
    for (const cd& r : ref) radius = std::max(radius, std::abs(r));
    double err = 0, det = 0;
    for (const cd& r : ref) {
      double best = 1e300;
      for (const cd& g : got) best = std::min(best, std::abs(g - r));
      err = std::max(err, best / radius);
    }
    // (28), built from Kononov's coefficients, at chain-rom's own roots (not at the companion form's, which satisfy it
    // by construction).
    for (const cd& r : got) {
      if (std::abs(r) < 1e-9 * radius) continue;  // the free chain's zero roots: (28) has 1/sigma terms there
      // (28): F_k = A'_k + C w/sigma - (kappa_{k-1}^2 + kappa_k^2)/sigma^2 on the diagonal, mu_ij (+ kappa^2/sigma^2).
      Eigen::MatrixXcd Phi = seed.cast<cd>() - Kel.cast<cd>() / (r * r);
      Phi.diagonal().array() += C * w / r;
      Eigen::JacobiSVD<Eigen::MatrixXcd> svd(Phi);
      det = std::max(det, svd.singularValues().minCoeff() / svd.singularValues().maxCoeff());
    }
    std::printf("  n = %2d: |M - Kononov (27)|/|M| = %.1e, roots against the companion form of (27) %.1e, "
                "det (28) at chain-rom's roots (smallest/largest singular value) %.1e\n", n, eM, err, det);
    EXPECT_EQ(got.size(), static_cast<std::size_t>(2 * n));
    EXPECT_LT(eM, 1e-14);
    EXPECT_LT(err, 1e-12);
    EXPECT_LT(det, 1e-12);
  }
}
