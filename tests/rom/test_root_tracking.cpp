// Root tracking (rom/analysis/root_tracking.hpp), the stability maps' root finder: on a three-body chain whose tanks carry
// response-fit-like viscous tables (40 damped poles each, some of them heavily damped pseudo-poles, as cavity-modes
// response fits have), the tracked roots must be the eigen-solver's, point by point along a line and over a 2-D map,
// and a start that cannot lead to the whole set of roots must be refused, never accepted.
#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "root_newton.hpp"
#include "root_tracking.hpp"
#include "rom_test_util.hpp"
#include "scene.hpp"
#include "spectrum.hpp"
#include "sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

// A table with the sphere's metadata at Ek = 1e-3 (make_viscous_tables.sh) and `modes` made-up damped poles: lambda
// over the fits' window (-1.4, 1.9), decays from 1e-3 to 0.3, the last four heavily damped (20 to 80), and residues
// of random size and phase that add up to about 90 % of the sum rule.
std::string fit_like_table(int modes, unsigned seed) {
  rc::ModeTable t = rc::read_mode_table(std::string(RC_VISCOUS_TABLES) + "/sphere_ek1e-3.h5");
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (auto* v : {&t.kappa, &t.lambda, &t.E, &t.a, &t.N2, &t.residual, &t.spread, &t.dlambda, &t.dE, &t.decay,
                  &t.E_imag, &t.a_imag})
    v->clear();
  t.members.clear();
  t.converged.clear();
  t.galerkin = {};  // its poles are no modes (a response fit's have no Galerkin matrices)
  double sum = 0;
  for (int l = 0; l < modes; ++l) {
    const double lambda = -1.4 + 3.3 * u(gen);
    const double decay = l < modes - 4 ? std::pow(10.0, -3 + 2.5 * u(gen)) : 20 + 60 * u(gen);
    const cd E = std::polar(1.8 * t.sum_rule / modes * (0.2 + 1.6 * u(gen)) / 2, 0.6 * (u(gen) - 0.5));
    const cd a = std::sqrt(E / 2.0);  // E = 2 a^2 / N^2 with N^2 = 1
    t.kappa.push_back(2 / lambda);  // the table identity kappa = 2/lambda
    t.lambda.push_back(lambda);
    t.decay.push_back(decay);
    t.E.push_back(E.real());
    t.E_imag.push_back(E.imag());
    t.a.push_back(a.real());
    t.a_imag.push_back(a.imag());
    t.N2.push_back(1);
    for (auto* v : {&t.residual, &t.spread, &t.dlambda, &t.dE}) v->push_back(0);
    t.members.push_back(1);
    t.converged.push_back(1);
    sum += E.real();
  }
  t.coverage = sum / t.sum_rule;
  const std::string file = std::string(RC_VISCOUS_TABLES) + "/fit_like_" + std::to_string(seed) + ".h5";
  return test::write_table(t, file).string();
}

// Three spinning bodies standing on a fixed point, like data/scenes/default.toml, each tank a fit-like table.
Scene chain_scene(double friction) {
  const double spins[] = {300, 250, 200}, masses[] = {3, 2, 1}, A[] = {0.066, 0.03, 0.01}, C[] = {0.02, 0.01, 0.004};
  const double com[] = {0.12, 0.10, 0.07}, next[] = {0.30, 0.25, 0}, scale = 0.04;
  std::ostringstream s;
  s.precision(17);
  s << "[system]\nkind = \"fixed\"\ngravity = 9.81\n";
  for (int k = 0; k < 3; ++k) {
    s << "[[body]]\nmass = " << masses[k] << "\nA = " << A[k] << "\nC = " << C[k] << "\ncom = " << com[k]
      << "\nspin = " << spins[k] << "\n";
    if (k < 2) s << "next_joint = " << next[k] << "\n";
    s << "[body.cavity]\ntable = \"" << fit_like_table(40, 11 + k) << "\"\ndensity = 1000.0\nscale = " << scale
      << "\ncenter = " << com[k] << "\nviscosity = " << 1e-3 * spins[k] * scale * scale << "\n";
  }
  s << "[[joint]]\nstiffness = 200.0\nfriction = " << friction << "\n[[joint]]\nstiffness = 100.0\n";
  return parse_scene_text(s.str(), ".", "fit-like-chain");
}

std::vector<cd> as_vector(const Eigen::VectorXcd& v) { return {v.data(), v.data() + v.size()}; }

}  // namespace

// Along a line of 60 stiffnesses of joint 1 (0 to 600 N m/rad), each point tracked from the one before: the tracked
// set is the eigen-solver's to its accuracy, and Newton on det Phi (root_newton.hpp) started from each tracked root
// stays there.
TEST(RootTracking, TrackedRootsAreTheEigenRootsAlongALine) {
  for (const double friction : {0.0, 0.02}) {
    Scene s = chain_scene(friction);
    Eigen::VectorXcd roots;
    double radius = 0, worst_eigen = 0, worst_newton = 0;
    int tracked = 0, sweeps = 0, newton_failed = 0;
    for (int i = 0; i < 60; ++i) {
      s.joints[0].stiffness = 10.0 * i;
      const ChainModel m = build_model(s);
      const Eigen::VectorXcd eigen = verdict_roots(m);
      const double scale = verdict_radius(verdict_from_roots(m, eigen));
      if (i > 0) {
        const TrackedRoots t = track_roots(m, roots, radius);
        ASSERT_TRUE(t.ok) << "stiffness " << s.joints[0].stiffness << ": " << t.why;
        ++tracked;
        sweeps = std::max(sweeps, t.sweeps);
        worst_eigen = std::max(worst_eigen, test::root_set_distance(as_vector(t.sigma), as_vector(eigen), scale));
        for (const cd z : t.sigma) {
          const NewtonRoot nr = newton_root(m, z, scale);
          if (nr.converged) worst_newton = std::max(worst_newton, std::abs(nr.sigma - z) / scale);
          else ++newton_failed;
        }
        roots = t.sigma;
      } else {
        roots = eigen;
      }
      radius = scale;
    }
    std::printf("  friction %.2f: %d points tracked (%ld roots each, at most %d sweeps); against the eigen-solver "
                "%.1e, Newton moves a tracked root %.1e (relative to the oscillating roots' radius; %d of its runs "
                "did not converge)\n",
                friction, tracked, static_cast<long>(roots.size()), sweeps, worst_eigen, worst_newton, newton_failed);
    EXPECT_LT(worst_eigen, 1e-9);
    EXPECT_LT(worst_newton, 1e-11);
    EXPECT_EQ(newton_failed, 0);  // else the Newton figure would rest on fewer roots than it says
  }
}

// A start with one root twice (and so one missing), or of the wrong size, never yields an accepted set that is not
// the eigen-solver's: the iteration either repairs it (Aberth's repulsion) or the checks refuse it.
TEST(RootTracking, RefusesAStartThatIsNotTheWholeSet) {
  const Scene s = chain_scene(0.0);
  const ChainModel m = build_model(s);
  const Eigen::VectorXcd eigen = verdict_roots(m);
  const double scale = verdict_radius(verdict_from_roots(m, eigen));
  for (const double offset : {0.0, 1e-3}) {  // the same root exactly twice, or twice a hair apart
    int repaired = 0, refused = 0;
    std::string why;
    for (int j = 1; j < eigen.size(); j += 7) {
      Eigen::VectorXcd start = eigen;
      start[j] = start[j - 1] + offset * scale;  // root j - 1 twice, root j missing
      const TrackedRoots t = track_roots(m, start, scale);
      if (t.ok) {
        ++repaired;
        EXPECT_LT(test::root_set_distance(as_vector(t.sigma), as_vector(eigen), scale), 1e-9) << "duplicate at " << j;
      } else {
        ++refused;
        why = t.why;
      }
    }
    std::printf("  a start root duplicated %s: %d repaired, %d refused%s%s\n", offset == 0 ? "exactly" : "1e-3 apart",
                repaired, refused, why.empty() ? "" : ", e.g. ", why.c_str());
  }
  const TrackedRoots shorter = track_roots(m, eigen.head(eigen.size() - 1), scale);
  EXPECT_FALSE(shorter.ok);
  EXPECT_EQ(shorter.why, "the number of roots changed");
}

// The root sum that closes the check is the first-order matrix's trace (first_order_trace against B itself).
TEST(RootTracking, TraceWithoutTheMatrixIsTheMatrixTrace) {
  for (const double friction : {0.0, 0.02}) {
    const ChainModel m = build_model(chain_scene(friction));
    const cd direct = build_first_order(m).B.trace(), closed = first_order_trace(m);
    std::printf("  friction %.2f: tr B = %.12e%+.12ei, without B %.1e off\n", friction, direct.real(), direct.imag(),
                std::abs(direct - closed) / std::abs(direct));
    EXPECT_LT(std::abs(direct - closed), 1e-12 * std::abs(direct));
  }
}

// A 12 x 12 map (joint 1's stiffness x gravity): tracked, every point but the first, and the same verdicts, counts of
// non-real roots and growth rates as with the eigen-solver at every point.
TEST(RootTracking, TrackedMapIsTheEigenMap) {
  const Scene s = chain_scene(0.01);
  const SweepAxis a1{parse_param_key("joint[1].stiffness", s), 0, 400, 12};
  const SweepAxis a2{parse_param_key("system.gravity", s), 0, 20, 12};
  TableCache tables;
  const SweepResult tracked = run_sweep(s, tables, a1, a2, 2, {}, true);
  const SweepResult eigen = run_sweep(s, tables, a1, a2, 2, {}, false);
  ASSERT_EQ(tracked.failed, 0);
  ASSERT_EQ(eigen.failed, 0);
  EXPECT_EQ(tracked.tracked, 143) << tracked.first_fallback;
  EXPECT_EQ(eigen.tracked, 0);
  double worst = 0;
  int stable = 0;
  for (std::size_t p = 0; p < tracked.points.size(); ++p) {
    const Verdict& a = tracked.points[p].verdict;
    const Verdict& b = eigen.points[p].verdict;
    EXPECT_EQ(a.stable, b.stable) << "point " << p;
    EXPECT_EQ(a.nonreal, b.nonreal) << "point " << p;
    worst = std::max(worst, std::abs(a.margin - b.margin) / verdict_radius(b));
    stable += a.stable;
  }
  std::printf("  %d of 144 points stable; growth rates tracked against eigen-solved: %.1e of the roots' radius; "
              "%.3f s against %.3f s\n", stable, worst, tracked.wall_seconds, eigen.wall_seconds);
  EXPECT_LT(worst, 1e-10);
}

// A viscous table holds one Ekman number: a spin-factor sweep of the viscous chain fails, with the Ekman mismatch
// named, at every factor but 1 — the CSV gets nan there, never a number from the wrong Ekman number.
TEST(RootTracking, SpinFactorOfAViscousChainFailsAwayFromItsEkman) {
  const Scene s = chain_scene(0.0);
  const SweepAxis ax{parse_param_key("system.spin_factor", s), 0.5, 1.5, 3};
  TableCache tables;
  const SweepResult r = run_sweep(s, tables, ax, std::nullopt, 1);
  ASSERT_EQ(r.points.size(), 3u);
  EXPECT_EQ(r.failed, 2);
  EXPECT_TRUE(r.points[1].ok);
  EXPECT_NE(r.points[0].error.find("was made for ekman"), std::string::npos) << r.points[0].error;
  std::printf("  factor 0.5: %s\n", r.points[0].error.c_str());
}

}  // namespace rc::rom
