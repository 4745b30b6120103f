// cavity-modes against docs/physics.md §2's closed forms, at default settings unless a test says otherwise.
// Every comparison prints its error.
#include "cavity_table.hpp"
#include "closed_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace rc::modes;

namespace {

TableRequest request(const std::string& kind, std::map<std::string, double> dims) {
  TableRequest r;
  r.shape.kind = kind;
  r.shape.dims = std::move(dims);
  r.mesh.order = 6;  // the program's default
  return r;
}

double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }

void expect_spheroid(double a, double c) {
  auto req = request("spheroid", {{"a", a}, {"c", c}});
  const auto t = compute_mode_table(req);
  const auto x = exact::spheroid(a, c);
  ASSERT_GE(t.size(), 1u);
  std::printf("spheroid a=%g c=%g: lambda err %.2e, E err %.2e, J_zh err %.2e, coverage %.12f (%.2f s)\n", a, c,
              rel(t.lambda[0], x.mode.lambda), rel(t.E[0], x.mode.E), rel(t.J_zh, x.J_zh), t.coverage,
              t.wall_seconds);
  EXPECT_LE(rel(t.lambda[0], x.mode.lambda), 1e-8);
  EXPECT_LE(rel(t.E[0], x.mode.E), 1e-8);
  EXPECT_LE(rel(t.J_zh, x.J_zh), 1e-8);
  EXPECT_LE(rel(t.A_f, x.A_f), 1e-9);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LE(t.E[i], 1e-8 * t.E[0]) << "cluster " << i;
}

// a cluster flagged converged must agree with its exact mode to the flag's tolerance (the flag
// compares with one order lower, so it is conservative); the dominant cluster must be flagged converged.
void expect_honest_convergence_flags(const rc::ModeTable& t, const std::vector<exact::Mode>& modes) {
  ASSERT_EQ(t.converged.size(), t.size());
  EXPECT_EQ(t.converged[0], 1);
  int flagged = 0;
  double worst = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!t.converged[i]) continue;
    ++flagged;
    const auto nearest = std::min_element(modes.begin(), modes.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.kappa - t.kappa[i]) < std::abs(b.kappa - t.kappa[i]);
    });
    const double err = std::max(rel(t.E[i], nearest->E), rel(t.kappa[i], nearest->kappa));
    worst = std::max(worst, err);
    EXPECT_LE(err, t.convergence_tolerance) << "cluster " << i + 1 << " flagged converged";
  }
  std::printf("  %d of %zu clusters flagged converged (against %s); worst error of a flagged one %.2e\n", flagged,
              t.size(), t.convergence_reference.c_str(), worst);
}

// Matches each of the five largest computed clusters to the exact mode of nearest κ.
void expect_cylinder(double height) {
  auto req = request("cylinder", {{"radius", 1.0}, {"height", height}});
  const auto t = compute_mode_table(req);
  const auto modes = exact::cylinder_modes(1.0, height);
  const double jzh = exact::cylinder_zhukovsky(1.0, height);
  std::printf("cylinder 2h/a=%g: %ld dofs, J_zh err %.2e, coverage %.6f, %.2f s\n", height, t.ndof,
              rel(t.J_zh, jzh), t.coverage, t.wall_seconds);
  EXPECT_LE(rel(t.J_zh, jzh), 1e-7);
  ASSERT_GE(t.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const auto nearest = std::min_element(modes.begin(), modes.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.kappa - t.kappa[i]) < std::abs(b.kappa - t.kappa[i]);
    });
    std::printf("  #%zu kappa %.12f (exact %.12f, n=%d j=%d) err %.2e   E %.12e err %.2e\n", i + 1, t.kappa[i],
                nearest->kappa, nearest->axial, nearest->radial, rel(t.kappa[i], nearest->kappa), t.E[i],
                rel(t.E[i], nearest->E));
    EXPECT_LE(rel(t.kappa[i], nearest->kappa), 1e-6) << "cluster " << i + 1;
    EXPECT_LE(rel(t.E[i], nearest->E), 1e-6) << "cluster " << i + 1;
  }
  // The five largest exact modes are the five largest clusters (none missed by the survey).
  for (std::size_t i = 0; i < 5; ++i) EXPECT_LE(rel(t.E[i], modes[i].E), 1e-6) << "exact mode " << i + 1;
  expect_honest_convergence_flags(t, modes);
}

}  // namespace

TEST(CavityTables, SphereHasOneCouplingCluster) {
  auto req = request("sphere", {{"radius", 1.0}});
  req.selection.modes = 5;
  const auto t = compute_mode_table(req);
  const double E = 8 * std::numbers::pi / 15;
  ASSERT_GE(t.size(), 1u);
  std::printf("sphere: lambda err %.2e, E err %.2e, J_zh %.2e, coverage - 1 = %.2e, next E/E1 %.2e\n",
              std::abs(t.lambda[0] - 1), rel(t.E[0], E), t.J_zh, t.coverage - 1,
              t.size() > 1 ? t.E[1] / t.E[0] : 0.0);
  EXPECT_LE(std::abs(t.lambda[0] - 1), 1e-8);
  EXPECT_LE(rel(t.E[0], E), 1e-8);
  EXPECT_LE(std::abs(t.J_zh), 1e-10);
  EXPECT_LE(std::abs(t.coverage - 1), 1e-8);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LE(t.E[i], 1e-8 * t.E[0]) << "cluster " << i;
}

TEST(CavityTables, OblateSpheroid) { expect_spheroid(1.0, 0.5); }
TEST(CavityTables, ProlateSpheroid) { expect_spheroid(1.0, 2.0); }
TEST(CavityTables, CylinderHeightOne) { expect_cylinder(1.0); }
TEST(CavityTables, CylinderHeightTwo) { expect_cylinder(2.0); }
TEST(CavityTables, CylinderHeightFour) { expect_cylinder(4.0); }

// A structured mesh fine in r and coarse in z (--radial-size) resolves the high radial modes that the
// default isotropic mesh does not (there the j = 5..9 modes are off by 2e-5..4e-4 in E): the 12 largest
// exact modes of the 2h/a = 2 cylinder, found and right to 1e-6, on a mesh of 16 x 4 cells.
void expect_structured_cylinder(std::size_t count, bool fill_gaps) {
  auto req = request("cylinder", {{"radius", 1.0}, {"height", 2.0}});
  req.mesh.size = 0.5;
  req.mesh.radial_size = 1.0 / 16;
  req.selection.modes = static_cast<int>(count);
  req.clusters.fill_gaps = fill_gaps;
  req.check_convergence = false;
  const auto t = compute_mode_table(req);
  const auto modes = exact::cylinder_modes(1.0, 2.0);
  std::printf("structured cylinder 2h/a=2: %ld dofs, %.2f s, %s\n", t.ndof, t.wall_seconds, t.solver.c_str());
  ASSERT_EQ(t.size(), count);
  for (std::size_t i = 0; i < count; ++i) {
    std::printf("  exact #%zu n=%d j=%d kappa %.6f E %.6e: table kappa err %.2e, E err %.2e\n", i + 1, modes[i].axial,
                modes[i].radial, modes[i].kappa, modes[i].E, rel(t.kappa[i], modes[i].kappa), rel(t.E[i], modes[i].E));
    EXPECT_LE(rel(t.kappa[i], modes[i].kappa), 1e-6) << "exact mode " << i + 1;
    EXPECT_LE(rel(t.E[i], modes[i].E), 1e-6) << "exact mode " << i + 1;
  }
}

TEST(CavityTables, StructuredCylinderResolvesHighRadialModes) { expect_structured_cylinder(12, false); }

// The survey has no node for the 15th largest mode (n = 0, j = 8, measured); --fill-gaps finds it.
TEST(CavityTables, GapSearchFindsTheModesTheSurveyMissed) { expect_structured_cylinder(15, true); }

// inertial waves focus at a cone's apex; at modest resolution its clusters do not converge, and a
// table must say so rather than present them as converged.
TEST(CavityTables, ConeClustersAreNotPresentedAsConverged) {
  auto req = request("cone", {{"radius", 1.0}, {"height", 1.0}});
  req.mesh.order = 4;
  req.mesh.size = 0.25;
  req.selection.modes = 5;
  const auto t = compute_mode_table(req);
  ASSERT_EQ(t.converged.size(), t.size());
  int positive_unconverged = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::printf("  cone cluster %zu: lambda %.6f E %.4e dlambda %.1e dE %.1e converged %d\n", i + 1, t.lambda[i],
                t.E[i], t.dlambda[i], t.dE[i], t.converged[i]);
    if (t.lambda[i] > 0 && !t.converged[i]) ++positive_unconverged;
    EXPECT_EQ(t.converged[i], t.dlambda[i] <= t.convergence_tolerance && t.dE[i] <= t.convergence_tolerance);
  }
  EXPECT_GE(positive_unconverged, 1);
  // The bands cover (−2, 2) and carry the whole spectral weight (Gauss rule: exactly A_f − J_zh).
  double band_sum = 0;
  for (double e : t.bands.E) band_sum += e;
  EXPECT_DOUBLE_EQ(t.bands.lo.front(), -2.0);
  EXPECT_DOUBLE_EQ(t.bands.hi.back(), 2.0);
  EXPECT_NEAR(band_sum, t.sum_rule, 1e-10 * t.sum_rule);
}

TEST(CavityTables, RejectsBadSelection) {
  auto req = request("sphere", {{"radius", 1.0}});
  req.selection.coverage = 1.5;
  EXPECT_THROW(compute_mode_table(req), std::runtime_error);
}
