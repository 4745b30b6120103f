// The chain at two spins (rom/general/periodic_system.hpp, floquet.hpp; docs/rom.md, "Bodies at different spins"):
// periodic coefficients, roots by Floquet's theory. Checked against chains whose roots are known another way:
// (a) a chain at one spin seen from a frame that it turns against (its coefficients periodic there) must give the
// roots of its own frame, modulo the period's frequency Ω; (b) axisymmetric bodies with tanks at different spins are
// (26), which takes each body's spin exactly; (c) a platform and a rotor, both without axial symmetry, grow at the
// rate the nonlinear chain (rigid bodies at any angle, a separate model) grows at; (d) the Magnus monodromy converges
// at sixth order.
#include "bench.hpp"
#include "ellipsoid_table.hpp"
#include "floquet.hpp"
#include "general_chain.hpp"
#include "general_system.hpp"
#include "nonlinear_run.hpp"
#include "periodic_system.hpp"
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace rc::rom::test {
namespace {

using Roots = std::vector<std::complex<double>>;

// Largest distance between two root sets (greedy nearest matching), the real parts compared modulo Ω, over `scale`.
double distance_modulo(Roots a, Roots b, double omega, double scale) {
  if (a.size() != b.size()) return 1e300;
  const auto d = [omega](std::complex<double> x, std::complex<double> y) {
    const double re = x.real() - y.real();
    return std::hypot(re - omega * std::round(re / omega), x.imag() - y.imag());
  };
  double worst = 0;
  for (const auto& x : a) {
    auto it = std::min_element(b.begin(), b.end(), [&](auto p, auto q) { return d(p, x) < d(q, x); });
    worst = std::max(worst, d(*it, x) / scale);
    b.erase(it);
  }
  return worst;
}

// The roots without the n that decay fastest (beyond a monodromy's precision: floquet.hpp).
Roots without_fastest_decaying(Roots r, int n) {
  std::sort(r.begin(), r.end(), [](auto p, auto q) { return p.imag() < q.imag(); });
  r.resize(r.size() - static_cast<std::size_t>(n));
  return r;
}

// A heavy top with B ≠ A carrying a 1 : 0.8 : 0.6 ellipsoid of water on its axis, or two of them off it on opposite sides.
std::string top(double spin, double gravity, bool two_tanks) {
  write_table(ellipsoid_table(1, 0.8, 0.6, 0), test_dir() / "two_spins_ellipsoid.h5");
  std::string s = "[system]\nkind = \"fixed\"\ngravity = " + num(gravity) + "\n[[body]]\nmass = 3.0\nA = 0.2\nB = 0.15\n"
                  "C = 0.12\ncom = 0.1\nspin = " + num(spin) + "\n";
  const std::string tank = "[[body.cavity]]\ntable = \"two_spins_ellipsoid.h5\"\ndensity = 1000.0\nscale = 0.1\n"
                           "center = 0.05\n";
  if (!two_tanks) return s + tank;
  return s + tank + "offset = [0.15, 0.05]\n" + tank + "offset = [-0.15, -0.05]\n";
}

TEST(TwoSpins, AChainSeenFromAFrameItTurnsAgainstKeepsItsRoots) {
  struct Case { const char* what; double spin, gravity, frame; bool two_tanks; };
  const Case cases[] = {{"heavy top B != A, a tank on its axis, 20 rad/s", 20, 9.81, 13, false},
                        {"the same top slow, 3 rad/s (it falls)", 3, 9.81, 5, false},
                        {"the top without gravity (spinning about its least moment), two tanks off its axis", 20, 0,
                         15.5, true}};
  for (const Case& c : cases) {
    const Scene scene = parse_scene_text(top(c.spin, c.gravity, c.two_tanks), test_dir(), "t");
    const GeneralChain own = build_general_chain(scene);
    const GeneralChain seen = build_general_chain(scene, nullptr, c.frame);
    ASSERT_FALSE(own.periodic());
    ASSERT_TRUE(seen.periodic());
    const GeneralSpectrum expected = general_spectrum(own), got = general_spectrum(seen);
    const double omega = 2 * std::numbers::pi / seen.period;
    const int n = got.floquet_unresolved;
    const double err = distance_modulo(without_fastest_decaying(got.roots, n), without_fastest_decaying(expected.roots, n),
                                       omega, spectral_radius(expected.roots));
    std::printf("%s, seen from a frame at %g rad/s (Omega %g): %zu Floquet roots (%d Magnus steps a period, settled to "
                "%.1e rad/s; %d decaying beyond the monodromy's precision) against its own frame's %.2e of the spectral "
                "radius; growth %.6g and %.6g 1/s\n", c.what, c.frame, omega, got.roots.size(), got.floquet_steps,
                got.floquet_error, n, err, got.verdict.growth, expected.verdict.growth);
    EXPECT_LT(err, 1e-9);
    EXPECT_LE(n, c.spin > 10 ? 0 : 2);
    EXPECT_EQ(got.verdict.stable, expected.verdict.stable);
    EXPECT_NEAR(got.verdict.growth, expected.verdict.growth, 1e-9 * spectral_radius(expected.roots));
  }
}

// Three axisymmetric bodies, the first and the last with tanks (a spheroid's table, four modes), at 30, −12 and 55
// rad/s: in the frame turning with the first, the last one's tank turns at 25 rad/s, and the coefficients are
// periodic; (26) takes every spin in one constant system.
TEST(TwoSpins, AxisymmetricTanksAtTwoSpinsAreTheAxisymmetricChain) {
  for (const bool free_chain : {false, true}) {
    std::vector<Body> b(3);
    b[0].table = spheroid_file(1, 0.6);
    b[0].density = 900;
    b[0].center = 0.2;
    b[2].table = "four_modes.h5";
    if (!std::filesystem::exists(test_dir() / b[2].table)) write_table(four_mode_table(), test_dir() / b[2].table);
    b[1].A = 0.2;
    b[1].C = 0.3;
    b[0].spin = 30;
    b[1].spin = -12;
    b[2].spin = 55;
    const std::string text = scene_text(b, {{2.0, 0.0}, {1.5, 0.0}}, 9.81, free_chain);
    const Roots expected = turned(roots_of(compute_spectrum(model_of(text))), 30.0);
    const GeneralChain g = build_general_chain(parse_scene_text(text, test_dir(), "t"));
    ASSERT_TRUE(g.periodic());
    const GeneralSpectrum got = general_spectrum(g);
    const double err = distance_modulo(got.roots, expected, 25.0, spectral_radius(expected));
    std::printf("tanks at 30 and 55 rad/s, a body between at -12 (%s): %zu Floquet roots (%d steps a period) against "
                "(26)'s %.2e of the spectral radius\n", free_chain ? "free" : "fixed", got.roots.size(),
                got.floquet_steps, err);
    const Verdict v26 = compute_verdict(model_of(text));
    std::printf("  verdicts: Floquet %d (margin %.3e, tolerance %.3e), (26) %d (margin %.3e)\n", got.verdict.stable,
                got.verdict.margin, got.verdict.tolerance, v26.stable, v26.margin);
    EXPECT_LT(err, 1e-9);
    EXPECT_EQ(got.verdict.stable, v26.stable);
  }
}

// A dual-spin craft whose platform (B ≠ A, 20 rad/s) and rotor (A = 0.01, B = 0.012 kg m², 200 rad/s) are both
// without axial symmetry, on an elastic joint: unstable. Its growth against the nonlinear chain's released at 1e-7
// rad, measured on the envelope of the largest tilt (maxima over 0.1 s, a straight line in log through 2 s to 4.8 s).
std::string dual_spin(bool asymmetric_rotor, const std::string& model) {
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 3.0\nA = 0.2\nB = 0.15\nC = 0.12\ncom = 0.1\n"
         "next_joint = 0.2\nspin = 20.0\n[[body]]\nmass = 1.0\nA = 0.01\n" + std::string(asymmetric_rotor ? "B = 0.012\n" : "") +
         "C = 0.015\ncom = 0.03\nspin = 200.0\n[[joint]]\nstiffness = 400.0\nfriction = 0.0\n[initial]\n"
         "tilt = [[1e-7, 0.0], [1e-7, 0.0]]\nrate = [[0.0, 0.0], [0.0, 0.0]]\n[run]\nt_end = 5.0\noutput_step = 0.001\n"
         "model = \"" + model + "\"\n";
}

double envelope_growth(const History& h) {
  std::vector<double> t, log_peak;
  for (std::size_t i = 0; i + 100 <= h.t.size(); i += 100) {
    double peak = 0;
    for (std::size_t j = i; j < i + 100; ++j) peak = std::max(peak, h.u.row(static_cast<Eigen::Index>(j)).cwiseAbs().maxCoeff());
    if (h.t[i] >= 2 && h.t[i] <= 4.8) {
      t.push_back(h.t[i]);
      log_peak.push_back(std::log(peak));
    }
  }
  const double n = static_cast<double>(t.size());
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sl += log_peak[i];
    stt += t[i] * t[i];
    stl += t[i] * log_peak[i];
  }
  return (n * stl - st * sl) / (n * stt - st * st);
}

TEST(TwoSpins, AsymmetricRotorGrowsAsTheNonlinearChain) {
  const Scene scene = parse_scene_text(dual_spin(true, "nonlinear"), test_dir(), "t");
  const double floquet = general_spectrum(build_general_chain(scene)).verdict.growth;
  const double symmetric =
      general_spectrum(build_general_chain(parse_scene_text(dual_spin(false, "linear"), test_dir(), "t"))).verdict.growth;
  const NonlinearChain chain = nonlinear_chain(scene);
  const double measured = envelope_growth(integrate_nonlinear(chain, nonlinear_initial_state(scene, chain), scene.run).base);
  std::printf("platform and rotor without axial symmetry at 20 and 200 rad/s: Floquet growth %.5f 1/s, the nonlinear "
              "chain's %.5f (%.2e apart); with the rotor axisymmetric the chain grows at %.5f\n", floquet, measured,
              std::abs(floquet - measured) / measured, symmetric);
  EXPECT_NEAR(floquet, measured, 0.01 * measured);
  EXPECT_GT(std::abs(symmetric - measured), 0.1 * measured);  // the rotor's asymmetry is what the check sees
}

// `chain-rom bench` at two spins (general_bench.hpp): a heavy top with B ≠ A and the four-mode table at 40 rad/s, an
// unbalanced rotor at 90 rad/s above it. The Magnus run's state at t_end converges at sixth order down to its
// reference's own difference, and the body roots with 1, 2 and 4 rows kept approach those with all of them (the same
// chain with all kept: to the monodromy's settling).
TEST(TwoSpins, BenchMeasuresTheMagnusStepsAndTheKeptRows) {
  if (!std::filesystem::exists(test_dir() / "four_modes.h5")) write_table(four_mode_table(), test_dir() / "four_modes.h5");
  std::vector<Body> b(2);
  b[0].table = "four_modes.h5";
  b[0].spin = 40;
  b[0].center = 0.1;
  b[1].A = 0.02;
  b[1].C = 0.03;
  b[1].spin = 90;
  std::string text = scene_text(b, {{300.0, 0.0}}, 9.81, false, 0.0, "[initial]\ntilt = [[0.01, 0.0], [0.0, 0.0]]\n"
                                                                     "[run]\nt_end = 0.5\noutput_step = 0.01\n");
  text.insert(text.find("\nC = ") + 1, "B = 0.12\n");
  text.insert(text.rfind("\nC = ") + 1, "B = 0.024\n");
  const Scene scene = parse_scene_text(text, test_dir(), "t");
  ASSERT_TRUE(build_general_chain(scene).periodic());
  const BenchResult r = run_bench(scene);
  double reference = 1, order = 0;
  std::vector<double> magnus, roots;
  for (const BenchRow& row : r.rows) {
    if (row.method == "reference") reference = row.error;
    if (row.method == "magnus") magnus.push_back(row.error);
    if (row.part == "roots") roots.push_back(row.error);
  }
  for (std::size_t i = 1; i < magnus.size(); ++i)  // the asymptotic range: error ratio per halving of h
    if (magnus[i - 1] < 1e-4 && magnus[i] > 10 * reference) order = std::log2(magnus[i - 1] / magnus[i]);
  for (const double e : magnus) std::printf("  magnus row error %.3e\n", e);
  std::printf("bench at two spins (dimension %d): reference %.1e, %zu Magnus rows, order %.2f; body roots with 1, 2, 4 of "
              "4 rows: %.1e %.1e %.1e\n", r.dimension, reference, magnus.size(), order,
              roots.size() > 0 ? roots[0] : -1, roots.size() > 1 ? roots[1] : -1, roots.size() > 2 ? roots[2] : -1);
  EXPECT_LT(reference, 1e-10);
  EXPECT_NEAR(order, 6, 0.3);
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_GT(roots[0], 1e3 * roots[2]);
  EXPECT_LT(roots[2], 1e-9);
}

// The monodromy's error against one with 64 times the steps falls by 2^6 = 64 at each doubling (sixth order).
TEST(TwoSpins, MagnusMonodromyIsOfSixthOrder) {
  const Scene scene = parse_scene_text(top(20, 9.81, true), test_dir(), "t");
  const GeneralChain g = build_general_chain(scene, nullptr, 13.0);
  const double s = build_general_system(turned_chain(g, 0)).s;
  const Eigen::MatrixXd reference = magnus_transition(g, s, 0, g.period / 2048, 2048);
  double previous = 0;
  for (const int steps : {32, 64, 128}) {
    const double err = (magnus_transition(g, s, 0, g.period / steps, steps) - reference).norm() / reference.norm();
    std::printf("%d Magnus steps a period: monodromy error %.3e%s\n", steps, err,
                previous > 0 ? (", " + std::to_string(previous / err) + " times less than at half the steps").c_str() : "");
    if (previous > 0) {
      EXPECT_GT(previous / err, 48);
      EXPECT_LT(previous / err, 80);
    }
    previous = err;
  }
}

}  // namespace
}  // namespace rc::rom::test
