// chain-rom bench: the extended-precision reference against a closed form and against itself, the
// integrators' observed orders, the CSV, and the static correction's exactness at zero spin
// (Batyr Theorem 2) for any number of kept modes.
#include "bench.hpp"
#include "exact_propagation.hpp"
#include "reference_propagation.hpp"
#include "rom_test_util.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

namespace {

// A table of L modes sharing `coverage` of the sum rule of a spheroid a = 1, c = 1.5 (E_l ~ 0.7^l),
// with lambda of both signs in (-1.9, 1.9): a stand-in for a cavity-modes table that does not cover
// all of A_f - J_zh (the rest is what static_correction adds).
rc::ModeTable many_mode_table(int L, double coverage) {
  rc::ModeTable t = spheroid_table(1, 1.5);
  const double S = t.A_f - t.J_zh;
  double total = 0;
  for (int l = 0; l < L; ++l) total += std::pow(0.7, l);
  t.E.clear(); t.lambda.clear(); t.kappa.clear(); t.a.clear(); t.N2.clear(); t.residual.clear();
  for (int l = 0; l < L; ++l) {
    t.E.push_back(coverage * S * std::pow(0.7, l) / total);
    t.lambda.push_back((l % 2 ? -1.8 : 1.8) / (1 + 0.3 * l));
    t.kappa.push_back(2 / t.lambda.back());
    t.a.push_back(1);
    t.N2.push_back(2 / t.E.back());
    t.residual.push_back(0);
  }
  t.coverage = coverage;
  return t;
}

std::string run_text(double t_end) {
  return "[initial]\ntilt = [[0.01, 0.0], [0.0, -0.005]]\nrate = [[0.0, 0.1], [0.2, 0.0]]\n[run]\nt_end = " +
         num(t_end) + "\noutput_step = " + num(t_end) + "\n";
}

// Two spinning bodies on elastic joints: body 1 with the 12-mode table, body 2 with a spheroid.
Scene two_body_scene(double t_end, double spin_factor = 1) {
  write_table(many_mode_table(12, 0.9), test_dir() / "bench_12_modes.h5");
  Body b1; b1.mass = 2; b1.A = 0.05; b1.C = 0.08; b1.com = 0.05; b1.next = 0.15; b1.spin = 200 * spin_factor;
  b1.table = "bench_12_modes.h5"; b1.scale = 0.04; b1.center = 0.05; b1.static_correction = true;
  Body b2; b2.mass = 1; b2.A = 0.02; b2.C = 0.035; b2.com = 0.04; b2.spin = 150 * spin_factor;
  b2.table = spheroid_file(1, 0.7); b2.scale = 0.03; b2.center = 0.04;
  return parse_scene_text(scene_text({b1, b2}, {{5.0, 0}}, 9.81, false, 0, run_text(t_end)), test_dir(), "bench");
}

Eigen::VectorXcd initial_state(const Scene& s, const ChainModel& m, const FirstOrderSystem& f) {
  Eigen::VectorXcd u0(m.n), v0(m.n);
  for (int k = 0; k < m.n; ++k) { u0[k] = s.tilt[k]; v0[k] = s.rate[k]; }
  return f.to_state(m, u0, v0, Eigen::VectorXcd::Zero(m.n_modes()));
}

std::vector<BenchRow> rows_of(const BenchResult& r, const std::string& method) {
  std::vector<BenchRow> out;
  for (const BenchRow& x : r.rows)
    if (x.part == "work" && x.method == method) out.push_back(x);
  return out;
}

}  // namespace

// Heavy top without fluid: u(t) = a1 e^{i s1 t} + a2 e^{i s2 t}, s1,2 the roots of A' s^2 + C w s + a g = 0,
// evaluated in long double from the model's own (double) A', C w, a g. The reference must match it to
// long double rounding times the phase (|sigma| t), the double `exact` to double rounding times it.
TEST(Bench, ReferenceMatchesHeavyTopClosedForm) {
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 60;  // C^2 w^2 > 4 A' a g: stable
  const double t = 50.0;
  const Scene s = parse_scene_text(
      scene_text({b}, {}, 9.81, false, 0, "[initial]\ntilt = [[0.01, 0.002]]\nrate = [[0.05, -0.1]]\n[run]\nt_end = 50.0\noutput_step = 50.0\n"),
      test_dir(), "top");
  const ChainModel m = build_model(s);
  const FirstOrderSystem f = build_first_order(m);
  const Eigen::VectorXcd y0 = initial_state(s, m, f);
  // Closed form of the same (double) model: A' = M, C w = G, a g = -K, u0 and v0 as parsed.
  using LC = std::complex<long double>;
  const long double A = m.M(0, 0), Cw = m.G[0], ag = -m.K(0, 0);
  const long double disc = std::sqrt(Cw * Cw - 4 * A * ag);
  const long double s1 = (-Cw + disc) / (2 * A), s2 = (-Cw - disc) / (2 * A);
  const LC u0(s.tilt[0].real(), s.tilt[0].imag()), v0(s.rate[0].real(), s.rate[0].imag()), I(0, 1);
  const LC a1 = (v0 / I - s2 * u0) / (s1 - s2), a2 = u0 - a1;
  const long double tl = t;
  const LC u = a1 * std::exp(I * s1 * tl) + a2 * std::exp(I * s2 * tl);
  const LC v = I * s1 * a1 * std::exp(I * s1 * tl) + I * s2 * a2 * std::exp(I * s2 * tl);
  Eigen::VectorXcd exact(2);
  exact << cd(static_cast<double>(f.s * u.real()), static_cast<double>(f.s * u.imag())),
      cd(static_cast<double>(v.real()), static_cast<double>(v.imag()));
  const ReferenceState ref = reference_state(m, f.s, y0, t);
  const double err_ref = (ref.y - exact).norm() / exact.norm();
  ModalForm mf = modal_form(f, true, kRealTolerance);
  const double err_double = (modal_state_at(mf, y0, t) - exact).norm() / exact.norm();
  const double phase = std::abs(static_cast<double>(s2)) * t;
  std::printf("  heavy top, |sigma| t = %.0f rad: reference %.2e (eig vs expm %.2e), exact in double %.2e\n", phase,
              err_ref, ref.method_difference, err_double);
  EXPECT_EQ(ref.mantissa_bits, 64);
  // Rounding of the phase: ~eps |sigma| t, long double eps = 1.1e-19, double 2.2e-16.
  EXPECT_LT(err_ref, 20 * 1.1e-19 * phase);
  EXPECT_LT(ref.method_difference, 20 * 1.1e-19 * phase);
  EXPECT_LT(err_double, 20 * 2.2e-16 * phase);
  EXPECT_LT(err_ref, err_double / 100);
}

// A spinning chain with 13 fluid modes over a few periods: the two long double methods agree far below
// double rounding, the energy is conserved by the reference, and the double `exact` is at its rounding.
TEST(Bench, ReferenceChecksOnAFluidChain) {
  const Scene s = two_body_scene(0.2);
  const ChainModel m = build_model(s);
  const FirstOrderSystem f = build_first_order(m);
  const Eigen::VectorXcd y0 = initial_state(s, m, f);
  const ReferenceState ref = reference_state(m, f.s, y0, 0.2);
  ModalForm mf = modal_form(f, true, kRealTolerance);
  ASSERT_TRUE(mf.usable);
  const double err_double = (modal_state_at(mf, y0, 0.2) - ref.y).norm() / ref.y.norm();
  const BenchResult r = run_bench(s);
  double drift = -1;
  for (const BenchRow& x : r.rows)
    if (x.method == "reference" && x.parameter == "energy_drift") drift = x.error;
  std::printf("  %d-dimensional system, rho t = %.0f rad: eig vs expm (long double) %.2e, exact (double) vs reference "
              "%.2e, reference energy drift %.2e\n", f.dim(), r.spectral_radius * 0.2, ref.method_difference,
              err_double, drift);
  EXPECT_LT(ref.method_difference, 1e-16);
  EXPECT_LT(err_double, 1e-13);
  EXPECT_GE(drift, 0);
  EXPECT_LT(drift, 1e-14);
  EXPECT_LT(rows_of(r, "exact").at(0).error, 1e-13);
}

// Observed orders: gauss (2-stage Gauss-Legendre, order 4) between consecutive steps of the sweep
// (h halves), over errors well above its rounding floor; rk45's error falls with its tolerance.
TEST(Bench, GaussConvergesAtOrderFourAndRk45FollowsItsTolerance) {
  const BenchResult r = run_bench(two_body_scene(0.5));
  const auto gauss = rows_of(r, "gauss"), rk = rows_of(r, "rk45");
  ASSERT_GE(gauss.size(), 6u);
  ASSERT_GE(rk.size(), 6u);
  std::vector<double> orders;
  for (std::size_t i = 1; i < gauss.size(); ++i) {
    EXPECT_LT(gauss[i].value, gauss[i - 1].value);
    if (gauss[i].error > 1e-9 && gauss[i - 1].error < 1e-3)  // above the rounding floor (~1e-11 here)
      orders.push_back(std::log(gauss[i - 1].error / gauss[i].error) / std::log(gauss[i - 1].value / gauss[i].value));
  }
  ASSERT_GE(orders.size(), 3u);
  std::string list;
  for (double p : orders) {
    list += " " + std::to_string(p).substr(0, 4);
    EXPECT_GT(p, 3.6);
    EXPECT_LT(p, 4.4);
  }
  std::printf("  gauss: %zu step sizes, %.2e .. %.2e; observed orders%s\n", gauss.size(), gauss.front().error,
              gauss.back().error, list.c_str());
  // rk45: from 1e-4 to 1e-10 the error drops by at least 1e5 (tolerance proportionality is ~1e6).
  double e4 = -1, e10 = -1;
  for (const BenchRow& x : rk) {
    if (std::abs(x.value - 1e-4) < 1e-18) e4 = x.error;
    if (std::abs(x.value - 1e-10) < 1e-24) e10 = x.error;
  }
  std::printf("  rk45: tolerance 1e-4 -> error %.2e, 1e-10 -> %.2e (ratio %.1e)\n", e4, e10, e4 / e10);
  ASSERT_GT(e4, 0);
  ASSERT_GT(e10, 0);
  EXPECT_GT(e4 / e10, 1e5);
  for (std::size_t i = 1; i < rk.size(); ++i) EXPECT_GE(rk[i].steps, rk[i - 1].steps);
}

// docs/physics.md §3 / Batyr Theorem 2: at w = 0 the fluid acts through its Zhukovsky inertia alone, so with
// static_correction the tilt roots equal those of the rigid chain (fluid frozen as mass, transverse
// inertia J_zh) for ANY number of kept modes, to rounding; without it they do not, even with all 12
// modes kept (the table covers 0.9 of A_f - J_zh). The rigid chain is an independent model: no cavity.
TEST(Bench, StaticCorrectionIsExactAtZeroSpinForAnyKeptCount) {
  const rc::ModeTable t = many_mode_table(12, 0.9);
  write_table(t, test_dir() / "zhukovsky_12_modes.h5");
  // Batyr (2010)'s hanging pendulums (stable at w = 0), two of them with the table's cavity.
  Body b1; b1.mass = 2; b1.A = 0.3; b1.C = 0.01; b1.com = -0.2; b1.next = -0.4;
  Body b2; b2.mass = 1.5; b2.A = 0.2; b2.C = 0.01; b2.com = -0.15; b2.next = -0.35;
  Body b3; b3.mass = 1; b3.A = 0.1; b3.C = 0.01; b3.com = -0.1;
  for (Body* b : {&b1, &b3}) { b->table = "zhukovsky_12_modes.h5"; b->scale = 0.06; b->center = b->com; }
  const std::vector<Joint> joints = {{1.0, 0}, {0.5, 0}};
  std::vector<Body> rigid = {b1, b2, b3};
  for (Body* r : {&rigid[0], &rigid[2]}) {
    const double L = r->scale, mf = r->density * L * L * L * t.volume, Jzh = r->density * std::pow(L, 5) * t.J_zh;
    r->com = (r->mass * r->com + mf * r->center) / (r->mass + mf);
    r->A += Jzh + mf * r->center * r->center;
    r->mass += mf;
    r->table.clear();
  }
  const Spectrum sr = compute_spectrum(model_of(scene_text(rigid, joints, 9.81)));
  const auto exact = roots_of(sr);
  const double R = spectral_radius(exact);
  auto tilt = [&](const Spectrum& sp) {  // the fluid modes' roots sit at sigma = 0 when w = 0
    std::vector<cd> out;
    for (const auto& x : sp.roots)
      if (std::abs(x.sigma) > 1e-9 * R) out.push_back(x.sigma);
    return out;
  };
  double worst_corrected = 0, best_uncorrected = 1e300;
  for (int kept : {1, 2, 3, 5, 8, 12}) {
    for (bool corrected : {true, false}) {
      std::vector<Body> bodies = {b1, b2, b3};
      for (Body* b : {&bodies[0], &bodies[2]}) { b->modes = kept; b->static_correction = corrected; }
      const Spectrum sp = compute_spectrum(model_of(scene_text(bodies, joints, 9.81)));
      const auto roots = tilt(sp);
      ASSERT_EQ(roots.size(), exact.size()) << kept << " modes";
      const double err = root_set_distance(roots, exact, R);
      if (corrected) worst_corrected = std::max(worst_corrected, err);
      else best_uncorrected = std::min(best_uncorrected, err);
      std::printf("  %2d of 12 modes kept, %s: tilt roots vs Zhukovsky rigid chain %.2e\n", kept,
                  corrected ? "static correction   " : "no static correction", err);
    }
  }
  EXPECT_LT(worst_corrected, 1e-14);
  EXPECT_GT(best_uncorrected, 1e-4);
}

// The roots part of the bench: body 1's 12 modes kept 1, 2, 4, 8, 12, with and without correction, at
// the scene's spins and at zero spin; at zero spin the corrected rows are exact (to rounding).
TEST(Bench, RootsAgainstKeptModesRows) {
  const BenchResult r = run_bench(two_body_scene(0.05));
  int rows = 0;
  for (const BenchRow& x : r.rows) {
    if (x.part != "roots") continue;
    ++rows;
    EXPECT_EQ(x.body, 1);
    EXPECT_GE(x.error, 0);
    if (x.spin_factor == 0 && x.static_correction == 1) {
      EXPECT_LT(x.error, 1e-13) << x.value << " modes";
    }
    if (x.spin_factor == 0 && x.static_correction == 0) {
      EXPECT_GT(x.error, 1e-5) << x.value << " modes";
    }
    if (x.value == 12 && x.static_correction == 1) {
      EXPECT_LT(x.error, 1e-12);  // the reference itself, its eigenvalues found without eigenvectors (rounding)
    }
    EXPECT_NEAR(x.coverage, 0.9 * (1 - std::pow(0.7, x.value)) / (1 - std::pow(0.7, 12)), 1e-12);
  }
  EXPECT_EQ(rows, 2 * 5 * 2);  // 2 spins x {1, 2, 4, 8, 12} x {with, without}
}

// CSV: the header and 12 fields on every line; a missing folder is refused before anything is written.
TEST(Bench, CsvIsWellFormed) {
  const BenchResult r = run_bench(two_body_scene(0.05));
  const auto out = std::filesystem::path(RC_ROM_TEST_DIR) / "bench.csv";
  write_bench_csv(r, out);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "part,method,parameter,value,steps,body,static_correction,spin_factor,coverage,wall_seconds,"
                  "cpu_seconds,error");
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 11) << line;
    EXPECT_TRUE(line.rfind("work,", 0) == 0 || line.rfind("roots,", 0) == 0) << line;
  }
  EXPECT_EQ(n, r.rows.size());
  EXPECT_THROW(write_bench_csv(r, std::filesystem::path(RC_ROM_TEST_DIR) / "no_such_dir" / "b.csv"),
               std::runtime_error);
}

// Bad input: no [run] section, one line.
TEST(Bench, RefusesASceneWithoutRun) {
  Body b; b.spin = 10;
  const Scene s = parse_scene_text(scene_text({b}, {}, 9.81), test_dir(), "norun");
  try {
    run_bench(s);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "norun: run: missing [run] section (bench needs run.t_end)");
  }
}
