// The frequency response (rom/analysis/frequency_response.hpp) against the heavy top's closed form, the first-order
// system's own forced solve, and the nonlinear chain's steady oscillation under a harmonic moment in space.
#include "first_order_system.hpp"
#include "frequency_response.hpp"
#include "nonlinear_run.hpp"
#include "rom_test_util.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

// One heavy top, u = β − iα: A′ü + iCω u̇ − a g u = F (Kononov (26) for one body), so û = F/(−A′σ² − Cωσ − a g).
TEST(FrequencyResponse, HeavyTopIsTheClosedForm) {
  Body b; b.mass = 2; b.A = 0.05; b.C = 0.03; b.com = 0.1; b.spin = 50;
  const ChainModel m = build_model(parse_scene_text(scene_text({b}, {}, 9.81), test_dir(), "test-scene"));
  const FrequencyResponse r = frequency_response(m, 0, -40, 40, 801);
  double worst = 0;
  for (std::size_t i = 0; i < r.sigma.size(); ++i) {
    const double s = r.sigma[i];
    const cd exact = 1.0 / (-0.05 * s * s - 0.03 * 50 * s - 0.2 * 9.81);
    worst = std::max(worst, std::abs(r.tilt(static_cast<Eigen::Index>(i), 0) - exact) / std::abs(exact));
  }
  std::printf("  heavy top, 801 frequencies in [-40, 40] rad/s: relative to the closed form %.1e; %zu resonances "
              "(%.6f, %.6f)\n", worst, r.resonances.size(), r.resonances.at(0), r.resonances.at(1));
  EXPECT_LT(worst, 1e-12);  // measured 7.8e-14
  ASSERT_EQ(r.resonances.size(), 2u);  // the roots of A′σ² + Cωσ + a g
  const double disc = std::sqrt(0.03 * 0.03 * 2500 - 4 * 0.05 * 0.2 * 9.81);
  EXPECT_NEAR(std::min(r.resonances[0], r.resonances[1]), (-1.5 - disc) / 0.1, 1e-10);
  EXPECT_NEAR(std::max(r.resonances[0], r.resonances[1]), (-1.5 + disc) / 0.1, 1e-10);
}

// Z(σ)⁻¹ F against the first-order system (26) forced by F e^{iσt} on body K: (iσ − B) ŷ = (0, M_eff⁻¹ F e_K, 0),
// û = ŷ's first block / s — a separate assembly of the same equations (fluid in w = z + u̇). Two bodies with
// spheroid tanks and joint friction, every body forced in turn.
TEST(FrequencyResponse, IsTheFirstOrderSystemsForcedSolve) {
  Body b1; b1.mass = 2; b1.A = 0.1; b1.C = 0.08; b1.com = 0.1; b1.next = 0.3; b1.spin = 50;
  b1.table = spheroid_file(1.0, 1.6); b1.scale = 0.05; b1.center = 0.12;
  Body b2; b2.mass = 1; b2.A = 0.03; b2.C = 0.02; b2.com = 0.06; b2.spin = 70;
  b2.table = spheroid_file(1.0, 0.7); b2.scale = 0.04; b2.center = 0.05;
  const ChainModel m = build_model(parse_scene_text(scene_text({b1, b2}, {{3.0, 0.02}}, 9.81), test_dir(), "test-scene"));
  const FirstOrderSystem f = build_first_order(m);
  Eigen::MatrixXcd Meff = m.M_eff.cast<cd>();
  Meff += cd(0, 1) * m.M_eff_imag.cast<cd>();
  double worst = 0;
  int points = 0;
  for (int body = 0; body < m.n; ++body) {
    const FrequencyResponse r = frequency_response(m, body, -120, 120, 97);
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(m.n);
    F[body] = 1;
    for (std::size_t i = 0; i < r.sigma.size(); ++i) {
      Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(f.dim());
      rhs.segment(m.n, m.n) = Meff.lu().solve(F);
      const Eigen::MatrixXcd A = cd(0, r.sigma[i]) * Eigen::MatrixXcd::Identity(f.dim(), f.dim()) - f.B;
      const Eigen::VectorXcd u = A.fullPivLu().solve(rhs).head(m.n) / f.s;
      const Eigen::VectorXcd mine = r.tilt.row(static_cast<Eigen::Index>(i)).transpose();
      worst = std::max(worst, (mine - u).norm() / u.norm());
      ++points;
    }
  }
  std::printf("  two bodies, two tanks (%d modes), joint friction: %d frequencies x 2 bodies forced, Z^-1 F against "
              "the first-order solve: %.1e\n", m.n_modes(), points / 2, worst);
  EXPECT_LT(worst, 1e-9);
}

// The nonlinear chain (a separate model: rigid bodies at any angle, nonlinear_chain.hpp) under a harmonic moment
// h sin(Ωt) fixed in space, after its start has decayed: its tilt must be the response's steady oscillation
//   u(t) = (h_y + i h_x)/(2i) [H(Ω) e^{iΩt} − H(−Ω) e^{−iΩt}],
// F = M_y + i M_x being the moment in the tilts' convention (u = n_x − i n_y: a turn θ about +x gives u = iθ,
// about +y u = θ; virtual work M·δθ = Re(F̄ δu)). A gyroscopic pendulum (centre of mass below O_1) with friction at
// the support, so that every root decays; the difference relative to the amplitude falls as the amplitude squared.
TEST(FrequencyResponse, IsTheNonlinearChainsSteadyOscillation) {
  const double Omega = 2 * std::numbers::pi * 1.5;
  std::vector<double> rel;
  for (double h : {0.02, 0.01}) {
    const std::string body = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[support]\nfriction = 0.05\n"
                             "[[body]]\nmass = 2.0\nA = 0.05\nC = 0.03\ncom = -0.1\nspin = 30.0\n";
    const Scene linear = parse_scene_text(body, ".", "pendulum");
    const ChainModel m = build_model(linear);
    const Verdict v = compute_verdict(m);
    ASSERT_LT(v.growth, -0.05);  // every root decays
    const double t_end = std::ceil(25.0 / -v.growth);
    const std::string moment = "[body.moment]\nharmonic = [" + std::to_string(h) + ", " + std::to_string(0.5 * h) +
                               ", 0.0]\nfrequency = 1.5\n[run]\nt_end = " + std::to_string(t_end) +
                               "\noutput_step = 0.01\nmodel = \"nonlinear\"\ntolerance = 1e-11\n";
    const Scene forced = parse_scene_text(body + moment, ".", "pendulum");
    const NonlinearChain chain = nonlinear_chain(forced);
    const NonlinearHistory nl = integrate_nonlinear(chain, nonlinear_initial_state(forced, chain), forced.run);
    const cd Hp = frequency_response(m, 0, Omega, 2 * Omega, 2).tilt(0, 0);
    const cd Hm = frequency_response(m, 0, -Omega, Omega, 2).tilt(0, 0);
    const cd F(0.5 * h, h);  // h_y + i h_x
    double diff = 0, amplitude = 0;
    for (std::size_t j = 0; j < nl.base.t.size(); ++j) {
      const double t = nl.base.t[j];
      if (t < t_end - 2) continue;  // the last two seconds: three periods of the moment
      const cd steady = F / cd(0, 2) * (Hp * std::exp(cd(0, Omega * t)) - Hm * std::exp(cd(0, -Omega * t)));
      diff = std::max(diff, std::abs(nl.base.u(static_cast<Eigen::Index>(j), 0) - steady));
      amplitude = std::max(amplitude, std::abs(steady));
    }
    rel.push_back(diff / amplitude);
    std::printf("  moment %.3f N m at 1.5 Hz, %.0f s (slowest decay %.3f 1/s): steady tilt %.3e rad, nonlinear chain "
                "against the response %.2e of it\n", h, t_end, -v.growth, amplitude, rel.back());
  }
  std::printf("  halving the moment: the difference falls by %.2f (amplitude squared: 4)\n", rel[0] / rel[1]);
  EXPECT_LT(rel[1], 1e-3);
  EXPECT_GT(rel[0] / rel[1], 3.0);
}
