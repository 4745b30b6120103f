// The chain at two spins (rom/general/periodic_system.hpp, floquet.hpp; docs/rom.md, "Bodies at different spins"):
// periodic coefficients, roots by Floquet's theory. Checked against chains whose roots are known another way:
// (a) a chain at one spin seen from a frame that it turns against (its coefficients periodic there) must give the
// roots of its own frame, modulo the period's frequency Ω; (b) axisymmetric bodies with tanks at different spins are
// (26), which takes each body's spin exactly; (c) a platform and a rotor, both without axial symmetry, grow at the
// rate the nonlinear chain (rigid bodies at any angle, a separate model) grows at; (d) the Magnus monodromy converges
// at sixth order; (e) its steady response to a harmonic moment is (26)'s for axisymmetric bodies, the one-spin chain's
// seen from another frame, and the nonlinear chain's under the same moment.
#include "bench.hpp"
#include "ellipsoid_table.hpp"
#include "floquet.hpp"
#include "frequency_response.hpp"
#include "general_chain.hpp"
#include "general_response.hpp"
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
std::string three_axisymmetric_bodies(bool free_chain) {
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
  return scene_text(b, {{2.0, 0.0}, {1.5, 0.0}}, 9.81, free_chain);
}

TEST(TwoSpins, AxisymmetricTanksAtTwoSpinsAreTheAxisymmetricChain) {
  for (const bool free_chain : {false, true}) {
    const std::string text = three_axisymmetric_bodies(free_chain);
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

// (e) The steady response at two spins (periodic_response.hpp). Axisymmetric bodies and tanks at 30, −12 and 55 rad/s:
// (26) takes every spin in one constant system, so its tilt per unit moment is the steady response's A₊, and nothing
// else may appear — no mirror, no sideband. On the free chain the frequencies σ = 25k (the tank's turning) alias its
// drift at frequency 0 (a neutral Floquet motion the moment does not drive): there the response is the limit from
// either side, its sidebands zero to rounding over the limit's offset (about 1e-8); σ = 0 drives the drift: a root.
TEST(TwoSpins, ResponseOfAxisymmetricTanksAtTwoSpinsIsTheAxisymmetricChains) {
  for (const bool free_chain : {false, true}) {
    const std::string text = three_axisymmetric_bodies(free_chain);
    const GeneralChain g = build_general_chain(parse_scene_text(text, test_dir(), "t"));
    ASSERT_TRUE(g.periodic());
    for (int body = 0; body < 3; body += 2) {
      const FrequencyResponse expected = frequency_response(model_of(text), body, -40.0, 55.0, 39);
      const GeneralFrequencyResponse got = general_frequency_response(g, body, -40.0, 55.0, 39);
      double err = 0, rest = 0;
      for (Eigen::Index i = 0; i < expected.tilt.rows(); ++i) {
        const double size = expected.tilt.row(i).norm();
        err = std::max(err, (got.tilt.row(i) - expected.tilt.row(i)).norm() / size);
        rest = std::max({rest, got.mirror.row(i).norm() / size, got.sideband.row(i).norm() / size});
      }
      std::printf("axisymmetric tanks at two spins (%s), moment on body %d, 39 frequencies (%d Magnus steps a period): "
                  "tilt against (26)'s %.2e, mirror and sidebands %.2e (relative); %d at a root\n",
                  free_chain ? "free" : "fixed", body + 1, got.steps_per_period, err, rest, got.singular);
      EXPECT_LT(err, 1e-9);
      EXPECT_LT(rest, free_chain ? 1e-7 : 1e-9);
      EXPECT_EQ(got.singular, free_chain ? 1 : 0);
    }
  }
}

// A top with B ≠ A and a tank at 20 rad/s, seen from a frame at 13 rad/s (periodic there): the moment's tilt A₊ is
// its own frame's, and its mirror at −σ − 40 rad/s, which the frame at 13 counts among the sidebands (its own mirror
// frequency is −σ − 26), is the whole sideband.
TEST(TwoSpins, ResponseSeenFromAFrameTheChainTurnsAgainstIsItsOwn) {
  const Scene scene = parse_scene_text(top(20, 9.81, false), test_dir(), "t");
  const GeneralFrequencyResponse own = general_frequency_response(build_general_chain(scene), 0, -70.0, 50.0, 41);
  const GeneralFrequencyResponse seen =
      general_frequency_response(build_general_chain(scene, nullptr, 13.0), 0, -70.0, 50.0, 41);
  double tilt = 0, mirror = 0, sideband = 0, own_mirror = 0;
  for (Eigen::Index i = 0; i < own.tilt.rows(); ++i) {
    const double size = own.tilt.row(i).norm();
    tilt = std::max(tilt, (seen.tilt.row(i) - own.tilt.row(i)).norm() / size);
    mirror = std::max(mirror, seen.mirror.row(i).norm() / size);
    sideband = std::max(sideband, (seen.sideband.row(i) - own.mirror.row(i).cwiseAbs()).norm() / size);
    own_mirror = std::max(own_mirror, own.mirror.row(i).norm() / size);
  }
  std::printf("top B != A at 20 rad/s seen from a frame at 13, 41 frequencies: tilt against its own frame's %.2e, the "
              "frame's mirror %.2e, the sidebands against its own mirror (up to %.3g of the tilt) %.2e (relative)\n",
              tilt, mirror, own_mirror, sideband);
  EXPECT_LT(tilt, 1e-9);
  EXPECT_LT(mirror, 1e-9);
  EXPECT_LT(sideband, 1e-9);
  EXPECT_GT(own_mirror, 1e-3);  // the asymmetry is what the sidebands see
}

// A hanging platform (B ≠ A, 20 rad/s, friction at its support) and a rotor (B ≠ A, 90 rad/s) on an elastic joint with
// friction, driven by a moment 1e-4 N m sin(8 t) about x on the platform (the sum of ±F e^{±8it}, F = 1e-4/2 in (26)'s
// convention u = β − iα, F = M_y + i M_x: i·1e-4 sin 8t): the nonlinear chain's tilts over 20 s from rest, each frequency's
// amplitude by a Blackman–Harris window (sidelobes below 1e-4; the free motions decay or lie 8 rad/s or more away),
// against the steady response at σ = ±8: A₊ at ±8, the platform's mirror at −8 − 40, and the sidebands at 8 + 70k and
// −48 + 70k (the rotor turns against the platform at 70 rad/s).
std::string forced_dual_spin(bool nonlinear) {
  return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 3.0\nA = 0.2\nB = 0.15\nC = 0.12\ncom = -0.1\n"
         "next_joint = 0.2\nspin = 20.0\n" + std::string(nonlinear ? "[body.moment]\nharmonic = [1e-4, 0.0, 0.0]\n"
         "frequency = " + num(8 / (2 * std::numbers::pi)) + "\n" : "") + "[[body]]\nmass = 1.0\nA = 0.01\nB = 0.012\n"
         "C = 0.015\ncom = 0.03\nspin = 90.0\n[[joint]]\nstiffness = 400.0\nfriction = 0.5\n[support]\nfriction = 2.0\n"
         "[initial]\ntilt = [[0.0, 0.0], [0.0, 0.0]]\nrate = [[0.0, 0.0], [0.0, 0.0]]\n[run]\nt_end = 20.0\n"
         "output_step = 0.001\nmodel = \"nonlinear\"\n";
}

// The amplitude of e^{iνt} in u(t) by a four-term Blackman–Harris window.
std::complex<double> amplitude_at(const History& h, int body, double nu) {
  const double N = static_cast<double>(h.t.size()), a[4] = {0.35875, 0.48829, 0.14128, 0.01168};
  std::complex<double> sum = 0;
  double weight = 0;
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    const double x = 2 * std::numbers::pi * static_cast<double>(j) / (N - 1);
    const double w = a[0] - a[1] * std::cos(x) + a[2] * std::cos(2 * x) - a[3] * std::cos(3 * x);
    sum += w * h.u(static_cast<Eigen::Index>(j), body) * std::exp(std::complex<double>(0, -nu * h.t[j]));
    weight += w;
  }
  return sum / weight;
}

TEST(TwoSpins, ResponseIsTheNonlinearChainsUnderAHarmonicMoment) {
  const Scene forced = parse_scene_text(forced_dual_spin(true), test_dir(), "t");
  const NonlinearChain chain = nonlinear_chain(forced);
  const History h = integrate_nonlinear(chain, nonlinear_initial_state(forced, chain), forced.run).base;
  const GeneralChain g = build_general_chain(parse_scene_text(forced_dual_spin(false), test_dir(), "t"));
  ASSERT_TRUE(g.periodic());
  ASSERT_TRUE(general_spectrum(g).verdict.stable);
  const GeneralFrequencyResponse r = general_frequency_response(g, 0, -8.0, 8.0, 2);
  const std::complex<double> F(0.5e-4, 0);  // at σ = +8; −F at σ = −8
  for (int k = 0; k < 2; ++k) {
    const double size = std::abs(F * r.tilt(1, k));
    const double plus = std::abs(amplitude_at(h, k, 8) - F * r.tilt(1, k)) / size;
    const double minus = std::abs(amplitude_at(h, k, -8) + F * r.tilt(0, k)) / std::abs(F * r.tilt(0, k));
    const double mirror = std::abs(amplitude_at(h, k, -48) - F * r.mirror(1, k)) / std::abs(F * r.mirror(1, k));
    double sidebands = 0;
    for (int j = -4; j <= 4; ++j)
      if (j != 0) sidebands += std::norm(amplitude_at(h, k, 8 + 70 * j)) + std::norm(amplitude_at(h, k, -48 + 70 * j));
    const double sideband = std::abs(std::sqrt(sidebands) - std::abs(F) * r.sideband(1, k)) / (std::abs(F) * r.sideband(1, k));
    std::printf("body %d under 1e-4 N m sin(8t): the nonlinear chain's amplitude at +8 rad/s against the steady response "
                "%.2e, at -8 %.2e, the mirror at -48 (%.3g of the tilt) %.2e, the sidebands (%.3g) %.2e (relative)\n",
                k + 1, plus, minus, std::abs(r.mirror(1, k) / r.tilt(1, k)), mirror,
                r.sideband(1, k) / std::abs(r.tilt(1, k)), sideband);
    EXPECT_LT(plus, 1e-4);
    EXPECT_LT(minus, 1e-4);
    EXPECT_LT(mirror, 1e-3);
    EXPECT_LT(sideband, 1e-3);
  }
}

}  // namespace
}  // namespace rc::rom::test
