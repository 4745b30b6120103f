// Roots against closed forms: E = 0 (one body, Savchenko's chain), the sphere, Greenhill.
#include "characteristic.hpp"
#include "companion_check.hpp"
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

// E = 0, one body: (22) is A' sigma^2 + C w sigma + a g = 0 (multiply F by sigma^2; Kononov
// (26) has "= a g u" on the right, so gravity destabilises a top with a > 0).
TEST(Spectrum, OneBodyWithoutFluidIsTheLagrangeTop) {
  for (double spin : {100.0, 5.0}) {
    Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = spin;
    const ChainModel m = model_of(scene_text({b}, {}, 9.81));
    const Spectrum sp = compute_spectrum(m);
    const double A = 0.05, Cw = 0.03 * spin, ag = 0.2 * 9.81;
    const cd disc = std::sqrt(cd(Cw * Cw - 4 * A * ag));
    const std::vector<cd> exact = {(-Cw + disc) / (2 * A), (-Cw - disc) / (2 * A)};
    const double err = root_set_distance(roots_of(sp), exact, spectral_radius(exact));
    std::printf("  spin %g: roots %g%+gi, %g%+gi; relative error %.2e, det residual %.2e\n", spin,
                sp.roots[0].sigma.real(), sp.roots[0].sigma.imag(), sp.roots[1].sigma.real(),
                sp.roots[1].sigma.imag(), err, sp.det_residual);
    EXPECT_LT(err, 1e-13);
    EXPECT_LT(sp.det_residual, 1e-13);
    const bool stable_exact = Cw * Cw > 4 * A * ag;  // Maievski-Chetaev condition
    EXPECT_EQ(sp.stable, stable_exact);
    EXPECT_NEAR(sp.margin, std::abs(disc.imag()) / (2 * A), 1e-12 * spectral_radius(exact));
  }
}

// E = 0, two bodies with an elastic joint: (22)/(31) is Savchenko's quartic
//   (A1 s^2 + G1 s + k1)(A2 s^2 + G2 s + k2) - (M12 s^2 + kap)^2 = 0, k_i = a_i g - kap.
// Its coefficients, built by hand here, must be the elementary symmetric functions of the roots.
TEST(Spectrum, TwoBodiesWithoutFluidSatisfySavchenkoQuarticByVieta) {
  Body b1; b1.mass = 3; b1.A = 0.2; b1.C = 0.15; b1.com = 0.12; b1.next = 0.3; b1.spin = 80;
  Body b2; b2.mass = 1.5; b2.A = 0.04; b2.C = 0.03; b2.com = 0.08; b2.spin = 120;
  const double g = 9.81, kap = 4.0;
  const Spectrum sp = compute_spectrum(model_of(scene_text({b1, b2}, {{kap, 0}}, g)));
  const double A1 = 0.2 + 1.5 * 0.09, A2 = 0.04, a1 = 3 * 0.12 + 0.3 * 1.5, a2 = 1.5 * 0.08;
  const double M12 = 0.3 * a2, G1 = 0.15 * 80, G2 = 0.03 * 120, k1 = a1 * g - kap, k2 = a2 * g - kap;
  const double c4 = A1 * A2 - M12 * M12, c3 = A1 * G2 + G1 * A2,
               c2 = A1 * k2 + G1 * G2 + k1 * A2 - 2 * M12 * kap, c1 = G1 * k2 + k1 * G2, c0 = k1 * k2 - kap * kap;
  ASSERT_EQ(sp.roots.size(), 4u);
  cd e1 = 0, e2 = 0, e3 = 0, e4 = 1;
  const auto r = roots_of(sp);
  for (int i = 0; i < 4; ++i) {
    e1 += r[i];
    e4 *= r[i];
    for (int j = i + 1; j < 4; ++j) {
      e2 += r[i] * r[j];
      for (int k = j + 1; k < 4; ++k) e3 += r[i] * r[j] * r[k];
    }
  }
  const double R = spectral_radius(r);
  const double err = std::max({std::abs(e1 + c3 / c4) / R, std::abs(e2 - c2 / c4) / (R * R),
                               std::abs(e3 + c1 / c4) / (R * R * R), std::abs(e4 - c0 / c4) / (R * R * R * R)});
  std::printf("  Vieta relative error %.2e, det residual %.2e, stable %d\n", err, sp.det_residual, sp.stable);
  EXPECT_LT(err, 1e-12);
  EXPECT_LT(sp.det_residual, 1e-12);
}

// A sphere changes the roots only through its frozen mass: its one mode (lambda = w0, E = A_f = C_f)
// cancels its frozen transverse and axial inertia. Reference: the same chain with point masses,
// plus one root sigma = 0 per sphere (the mode's own root, at sigma = lambda - w0 = 0).
TEST(Spectrum, SphereActsOnlyThroughItsMass) {
  Body b1; b1.mass = 2; b1.A = 0.08; b1.C = 0.06; b1.com = 0.1; b1.next = 0.35; b1.spin = 60;
  b1.table = sphere_file(1.0); b1.scale = 0.06; b1.density = 900; b1.center = 0.0;  // on the fixed point
  Body b2; b2.mass = 1; b2.A = 0.03; b2.C = 0.02; b2.com = 0.05; b2.spin = 90;
  b2.table = sphere_file(1.0); b2.scale = 0.04; b2.density = 1000; b2.center = 0.12;
  const Spectrum with = compute_spectrum(model_of(scene_text({b1, b2}, {{2.0, 0}}, 9.81)));
  auto point_mass = [](Body b) {
    const double mf = b.density * std::pow(b.scale, 3) * 4.0 / 3.0 * M_PI;
    b.com = (b.mass * b.com + mf * b.center) / (b.mass + mf);
    b.A += mf * b.center * b.center;
    b.mass += mf;
    b.table.clear();
    return b;
  };
  const Spectrum ref = compute_spectrum(model_of(scene_text({point_mass(b1), point_mass(b2)}, {{2.0, 0}}, 9.81)));
  const auto r = roots_of(with);
  const double R = spectral_radius(r);
  const double err = root_set_distance(drop_smallest(r, 2), roots_of(ref), R);
  std::vector<cd> sorted = r;
  std::sort(sorted.begin(), sorted.end(), [](cd p, cd q) { return std::abs(p) < std::abs(q); });
  std::printf("  relative distance to the point-mass chain %.2e; sphere roots |sigma| %.1e, %.1e\n", err,
              std::abs(sorted[0]), std::abs(sorted[1]));
  EXPECT_EQ(r.size(), 2u * 2 + 2);
  EXPECT_LT(err, 1e-10);
  EXPECT_LT(std::abs(sorted[1]) / R, 1e-12);
  EXPECT_EQ(with.stable, ref.stable);
}

// Massless shell, spheroidal cavity a, a, c on the fixed point, g = 0: uniform rotation is
// unstable exactly for a < c < 3a (Greenhill). Also the roots against the closed-form quadratic
//   (A_f - E) s^2 + (A_f (w - l) + C_f w - E w) s + C_f w (w - l) = 0  (and s = 0).
TEST(Spectrum, GreenhillSpheroidUnstableExactlyForAlessThanCLessThan3A) {
  const double w = 20;
  for (double ratio : {0.5, 0.97, 1.03, 2.0, 2.97, 3.03, 4.0}) {
    Body b; b.mass = 0; b.A = 0; b.C = 0; b.com = 0; b.spin = w;
    b.table = spheroid_file(1.0, ratio); b.scale = 0.1; b.density = 1000; b.center = 0;
    const ChainModel m = model_of(scene_text({b}, {}, 0.0));
    const Spectrum sp = compute_spectrum(m);
    const rc::ModeTable t = spheroid_table(1.0, ratio);
    const double f = 1000 * 1e-5, Af = f * t.A_f, Cf = f * t.C_f, E = f * t.E[0], l = w * t.lambda[0];
    const double qa = Af - E, qb = Af * (w - l) + Cf * w - E * w, qc = Cf * w * (w - l);
    const cd disc = std::sqrt(cd(qb * qb - 4 * qa * qc));
    const std::vector<cd> exact = {0.0, (-qb + disc) / (2 * qa), (-qb - disc) / (2 * qa)};
    const double err = root_set_distance(roots_of(sp), exact, spectral_radius(exact));
    const bool greenhill_unstable = ratio > 1 && ratio < 3;
    std::printf("  c/a = %.2f: margin %.4e rad/s, stable %d (Greenhill: %d), root error %.2e, det residual %.2e\n",
                ratio, sp.margin, sp.stable, !greenhill_unstable, err, sp.det_residual);
    EXPECT_EQ(sp.stable, !greenhill_unstable);
    EXPECT_LT(err, 1e-10);
    EXPECT_LT(sp.det_residual, 1e-10);
  }
}

// Every root of a general scene (3 bodies, fluid in two, elastic joints, friction) satisfies (29).
TEST(Spectrum, RootsSatisfyTheCharacteristicDeterminant) {
  Body b1; b1.mass = 2; b1.A = 0.1; b1.C = 0.08; b1.com = 0.1; b1.next = 0.3; b1.spin = 50;
  b1.table = spheroid_file(1.0, 1.6); b1.scale = 0.05; b1.center = 0.12;
  Body b2; b2.mass = 1.5; b2.A = 0.05; b2.C = 0.03; b2.com = 0.08; b2.next = 0.2; b2.spin = 70;
  Body b3; b3.mass = 1; b3.A = 0.03; b3.C = 0.02; b3.com = 0.06; b3.spin = 40;
  b3.table = spheroid_file(1.0, 0.6); b3.scale = 0.04; b3.center = 0.05;
  const ChainModel m = model_of(scene_text({b1, b2, b3}, {{3.0, 0.01}, {1.0, 0.02}}, 9.81, false, 0.005));
  const Spectrum sp = compute_spectrum(m);
  std::printf("  %zu roots, worst det residual %.2e, unchecked %d\n", sp.roots.size(), sp.det_residual, sp.unchecked);
  EXPECT_EQ(sp.roots.size(), 3u * 2 + 2);
  EXPECT_EQ(sp.unchecked, 0);
  EXPECT_LT(sp.det_residual, 1e-11);
  // and a point that is not a root has an O(1e-3..1) residual: the check can fail
  const double off = characteristic_residual(m, sp.roots[0].sigma * 1.01 + cd(0.5, 0), 100.0);
  std::printf("  residual away from a root %.2e\n", off);
  EXPECT_GT(off, 1e-6);
}

// Companion tables (rom/analysis/companion_check.hpp): a coarser-mesh table of the same cavity. An identical companion
// moves no root; one whose cluster differs by 1e-3 in E moves the roots that cluster shapes, and they are marked;
// a companion of another cavity is refused.
TEST(Spectrum, CompanionTableMarksTheRootsThatMove) {
  const rc::ModeTable t = spheroid_table(1, 0.7);
  rc::ModeTable moved = t;
  for (std::size_t i = 0; i < moved.size(); ++i) { moved.E[i] *= 1.001; moved.a[i] *= std::sqrt(1.001); }
  moved.sum_rule = moved.A_f - moved.J_zh;
  write_table(t, test_dir() / "companion_same.h5");
  write_table(moved, test_dir() / "companion_moved.h5");
  Body b;
  b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 60;
  b.table = spheroid_file(1, 0.7); b.scale = 0.05; b.center = 0.05;
  const std::string text = scene_text({b}, {}, 9.81);
  const auto with = [&](const std::string& companion) {
    std::string s = text;
    s.replace(s.find("table = "), 0, "companion = \"" + companion + "\"\n");
    return parse_scene_text(s, test_dir(), "test-scene");
  };
  for (const std::string name : {"companion_same.h5", "companion_moved.h5"}) {
    const Scene scene = with(name);
    ASSERT_TRUE(has_companions(scene));
    Spectrum sp = compute_spectrum(build_model(scene));
    mark_companion_shifts(sp, compute_spectrum(build_model(with_companions(scene))));
    std::printf("  %s: %d of %zu roots moved, largest move %.2e\n", name.c_str(), sp.companion_moved,
                sp.roots.size(), sp.companion_worst);
    if (name == "companion_same.h5") {
      EXPECT_EQ(sp.companion_moved, 0);
      EXPECT_LE(sp.companion_worst, 1e-12);
    } else {
      EXPECT_GE(sp.companion_moved, 1);
      EXPECT_GT(sp.companion_worst, kCompanionTolerance);  // a 1e-3 change of E moves its roots by 6.6e-6
    }
  }
  EXPECT_THROW(with_companions(with(sphere_file(1))), SceneError);
}

// The Sturm-type certificate (rom/analysis/real_root_certificate.hpp) on the Lagrange top next to its threshold
// C w = 2 sqrt(A a g): 2e-15 above it the two roots are real, 7.9e-7 apart, and the sign count proves both; 2e-15
// below it they are a complex pair with |Im sigma| = 4.0e-7, inside the tolerance 6.3e-7 that calls them real, and
// the count proves none: certificate and tolerance disagree, and the spectrum says so.
TEST(Spectrum, CertificateProvesRealRootsAndCatchesTheTolerance) {
  const double A = 0.05, C = 0.03, ag = 0.2 * 9.81, threshold = 2 * std::sqrt(A * ag) / C;
  for (const double delta : {-2e-15, 2e-15}) {
    Body b; b.mass = 2; b.A = A; b.C = C; b.com = 0.1; b.spin = threshold * (1 - delta);
    const Spectrum sp = compute_spectrum(model_of(scene_text({b}, {}, 9.81)));
    std::printf("  spin %.17g (1 - %g of the threshold): roots %.10g%+.3gi, %.10g%+.3gi; tolerance %.3g; "
                "certificate %d of %d; verdict %s\n", b.spin, delta, sp.roots[0].sigma.real(), sp.roots[0].sigma.imag(),
                sp.roots[1].sigma.real(), sp.roots[1].sigma.imag(), sp.tolerance, sp.certified_real,
                sp.certificate_roots, sp.stable ? "stable" : "unstable");
    EXPECT_TRUE(sp.stable);  // by the tolerance, both times
    EXPECT_EQ(sp.certificate_roots, 2);
    if (delta < 0) {
      EXPECT_EQ(sp.certified_real, 2);
      EXPECT_FALSE(sp.certificate_disagrees());
    } else {
      EXPECT_EQ(sp.certified_real, 0);
      EXPECT_TRUE(sp.certificate_disagrees());
    }
  }
  // Two tops on an elastic joint with oblate cavities, and the unstable Greenhill spheroid.
  Body b1, b2;
  b1.mass = 2; b1.A = 0.05; b1.C = 0.08; b1.com = 0.05; b1.next = 0.15; b1.spin = 200;
  b1.table = spheroid_file(1, 0.6); b1.scale = 0.04; b1.center = 0.05;
  b2 = b1; b2.spin = 150; b2.scale = 0.03;
  const Spectrum two = compute_spectrum(model_of(scene_text({b1, b2}, {{5.0, 0.0}}, 9.81)));
  std::printf("  two tops: %d of %d roots proven real (%d at sigma = 0); verdict %s\n", two.certified_real,
              two.certificate_roots, two.roots_at_zero, two.stable ? "stable" : "unstable");
  EXPECT_TRUE(two.stable);
  EXPECT_EQ(two.certified_real, two.certificate_roots);
  EXPECT_EQ(two.certificate_roots + two.roots_at_zero, static_cast<int>(two.roots.size()));
}
