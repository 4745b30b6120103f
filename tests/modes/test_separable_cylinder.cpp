// The separable cylinder solver (modes/separable/separable_cylinder.hpp, --method separable) against Stewartson's closed
// form (docs/physics.md §2), the J_zh series of the exact cylinder solution (docs/modes.md, "Separable cylinder solver"), its own discrete sum rule, exact fluid integrals, and the
// independent mesh method. Every comparison prints its error.
#include "cavity_table.hpp"
#include "closed_forms.hpp"
#include "separable_cylinder.hpp"
#include "separable_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace rc::modes;

namespace {

constexpr double kPi = std::numbers::pi;

double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }

TableRequest separable_request(double radius, double height, int modes) {
  TableRequest r;
  r.method = TableMethod::separable;
  r.shape = {"cylinder", {{"radius", radius}, {"height", height}}, {}};
  r.mesh.order = 0;  // the method's defaults, as the command line leaves them
  r.selection.modes = modes;
  return r;
}

// The table's rows are the `count` largest exact modes, in order, each to `tol` in κ and E; every row
// flagged converged is within the flag's tolerance of its exact mode. Returns the worst error.
double expect_largest_exact_modes(double radius, double height, std::size_t count, double tol, int max_axial = 4) {
  const auto t = compute_mode_table(separable_request(radius, height, static_cast<int>(count)));
  const auto modes = exact::cylinder_modes(radius, height, max_axial, 80.0);
  const double jzh = exact::cylinder_zhukovsky(radius, height);
  std::printf("cylinder a=%g 2h=%g: %ld dofs, %.3f s, J_zh err %.2e, coverage %.6f\n", radius, height, t.ndof,
              t.wall_seconds, rel(t.J_zh, jzh), t.coverage);
  EXPECT_LE(rel(t.J_zh, jzh), 1e-9);
  EXPECT_EQ(t.size(), count);
  double worst = 0;
  int flagged = 0;
  for (std::size_t i = 0; i < std::min(count, t.size()); ++i) {
    const double ek = rel(t.kappa[i], modes[i].kappa), eE = rel(t.E[i], modes[i].E);
    worst = std::max({worst, ek, eE});
    EXPECT_LE(ek, tol) << "exact mode " << i + 1 << " (n=" << modes[i].axial << " j=" << modes[i].radial << ")";
    EXPECT_LE(eE, tol) << "exact mode " << i + 1 << " (n=" << modes[i].axial << " j=" << modes[i].radial << ")";
    if (t.converged[i]) {
      ++flagged;
      EXPECT_LE(std::max(ek, eE), t.convergence_tolerance) << "row " << i + 1 << " flagged converged";
    }
  }
  std::printf("  %zu largest exact modes: worst relative error (kappa, E) %.2e; %d flagged converged\n", count,
              worst, flagged);
  return worst;
}

}  // namespace

// The cylinders 2h/a = 1, 2, 4 at default settings: the 20 largest exact modes, none missed, each to
// 1e-7 (issue: 1e-6; measured worst 7e-8), J_zh to 1e-9 (issue: 1e-7).
TEST(SeparableCylinder, TwentyLargestStewartsonModesHeightOne) { expect_largest_exact_modes(1, 1, 20, 1e-7); }
TEST(SeparableCylinder, TwentyLargestStewartsonModesHeightTwo) { expect_largest_exact_modes(1, 2, 20, 1e-7); }
TEST(SeparableCylinder, TwentyLargestStewartsonModesHeightFour) { expect_largest_exact_modes(1, 4, 20, 1e-7); }

// The defaults scale with the shape (separable_table.cpp): a flat and a tall cylinder, in other units.
TEST(SeparableCylinder, FlatAndTallCylinders) {
  expect_largest_exact_modes(1.0, 0.1, 20, 1e-7);      // 2h/a = 0.1
  expect_largest_exact_modes(0.1, 1.0, 20, 1e-7, 12);  // 2h/a = 10
}

// The annular cylinder b < r < a (cylinder --inner-radius; docs/physics.md §2, "annular cylinder"): no axis, the
// inner wall a wall like the outer one. The separable table's 10 largest rows at default settings against the J1 + cY1
// closed form, each to 1e-9 in κ and E, for a thin and a thick rod and a tall cavity, and Σ E over every eigenpair =
// A_f − J_zh.
TEST(SeparableCylinder, AnnularCylindersAreTheirClosedForm) {
  struct Ring { double b, a, height; };
  for (const Ring& g : {Ring{0.3, 1.0, 2.0}, Ring{0.6, 1.0, 2.0}, Ring{0.3, 1.0, 4.0}}) {
    TableRequest req = separable_request(g.a, g.height, 10);
    req.shape.dims["inner_radius"] = g.b;
    const auto t = compute_mode_table(req);
    const auto modes = exact::annular_cylinder_modes(g.b, g.a, g.height);
    ASSERT_GE(modes.size(), 10u);
    ASSERT_EQ(t.size(), 10u);
    double worst = 0;
    for (std::size_t i = 0; i < 10; ++i) {
      const double ek = rel(t.kappa[i], modes[i].kappa), eE = rel(t.E[i], modes[i].E);
      worst = std::max({worst, ek, eE});
      EXPECT_LE(std::max(ek, eE), 1e-9) << "b=" << g.b << " 2h=" << g.height << " mode " << i + 1;
    }
    SeparableGrid grid = separable_grid(req.shape, req.mesh);
    const auto s = solve_separable_cylinder(g.a, g.height, grid);
    const double m = kPi * (g.a * g.a - g.b * g.b) * g.height;
    const double A_f = m * ((g.a * g.a + g.b * g.b) / 4 + g.height * g.height / 12);
    std::printf("annulus b=%g a=%g 2h=%g: %ld dofs, %.3f s; 10 largest modes to %.2e (kappa, E); sum E - (A_f - J_zh) "
                "%.1e relative; A_f err %.1e\n", g.b, g.a, g.height, t.ndof, t.wall_seconds, worst,
                (s.sum_E - s.sum_rule) / s.sum_rule, rel(s.fluid.A_f, A_f));
    EXPECT_LE(std::abs(s.sum_E - s.sum_rule) / s.sum_rule, 1e-10);
    EXPECT_LE(rel(s.fluid.A_f, A_f), 1e-13);
  }
}

// Σ E over every eigenpair equals A_f − J_zh: an exact identity of the discretisation (docs/physics.md §2), here checked on
// every eigenpair of every coupled radial problem; the frozen-fluid integrals are exact.
TEST(SeparableCylinder, SumRuleAndFluidIntegrals) {
  const double a = 1.0, H = 2.0, m = kPi * a * a * H;
  const SeparableGrid g = SeparableGrid::graded(1.0, 2.0, 8, 12, 8, 2);
  const auto s = solve_separable_cylinder(a, H, g);
  std::printf("%zu eigenpairs: (sum E - (A_f - J_zh)) / (A_f - J_zh) = %.2e; volume err %.1e, A_f err %.1e, C_f err "
              "%.1e\n", s.modes.size(), (s.sum_E - s.sum_rule) / s.sum_rule, rel(s.fluid.volume, m),
              rel(s.fluid.A_f, m * (a * a / 4 + H * H / 12)), rel(s.fluid.C_f, m * a * a / 2));
  EXPECT_LE(std::abs(s.sum_E - s.sum_rule) / s.sum_rule, 1e-10);
  EXPECT_LE(rel(s.fluid.volume, m), 1e-14);
  EXPECT_LE(rel(s.fluid.A_f, m * (a * a / 4 + H * H / 12)), 1e-14);
  EXPECT_LE(rel(s.fluid.C_f, m * a * a / 2), 1e-14);
  EXPECT_LE(std::abs(s.fluid.centroid_z), 1e-14);
  for (const auto& mode : s.modes) {
    ASSERT_TRUE(std::isfinite(mode.E));
    EXPECT_GE(mode.E, 0.0);
    EXPECT_LE(mode.residual, 1e-12);
  }
}

// Flags on coarse user grids (the benchmark's sweep found these): every row flagged converged is within the
// flag's tolerance of its exact mode. Before the coarser grid merged neighbouring elements, halving the uniform
// count left the lid layers and the largest axial elements as they were, and the n = 2, j = 1 mode of the
// 2h/a = 1 cylinder was flagged (dE 2e-11) while 2.4e-6 off.
TEST(SeparableCylinder, ConvergenceFlagsAreHonestOnCoarseGrids) {
  struct Setting { double height; int order; double radial, axial; };
  int flagged = 0, rows = 0;
  double worst = 0;
  for (const Setting& g : {Setting{1, 6, 1.0 / 6, 0.5}, Setting{1, 6, 0.1, 0.3}, Setting{1, 4, 1.0 / 6, 0.5},
                           Setting{2, 6, 1.0 / 6, 0.5}, Setting{1, 6, 0.25, 0.75}}) {
    auto req = separable_request(1.0, g.height, 20);
    req.mesh.order = g.order;
    req.mesh.radial_size = g.radial;
    req.mesh.size = g.axial;
    const auto t = compute_mode_table(req);
    const auto modes = exact::cylinder_modes(1.0, g.height, 4, 80.0);
    for (std::size_t i = 0; i < t.size(); ++i) {
      ++rows;
      if (!t.converged[i]) continue;
      ++flagged;
      const auto nearest = std::min_element(modes.begin(), modes.end(), [&](const auto& a, const auto& b) {
        return std::abs(a.kappa - t.kappa[i]) < std::abs(b.kappa - t.kappa[i]);
      });
      const double err = std::max(rel(t.kappa[i], nearest->kappa), rel(t.E[i], nearest->E));
      worst = std::max(worst, err);
      EXPECT_LE(err, t.convergence_tolerance) << "2h/a=" << g.height << " P" << g.order << " h_r=" << g.radial
                                              << " h=" << g.axial << " row " << i + 1 << " (n=" << nearest->axial
                                              << " j=" << nearest->radial << ")";
    }
  }
  std::printf("coarse grids: %d of %d rows flagged converged, worst error of a flagged row %.2e\n", flagged, rows,
              worst);
}

// The labels (n, j) are Stewartson's axial and radial indices, so the convergence check matches like with like.
TEST(SeparableCylinder, LabelsAreStewartsonIndices) {
  const SeparableGrid g = SeparableGrid::graded(1.0, 2.0, 8, 12, 8, 2);
  const auto s = solve_separable_cylinder(1.0, 2.0, g);
  const auto modes = exact::cylinder_modes(1.0, 2.0, 4, 80.0);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_EQ(s.modes[i].axial, modes[i].axial) << "mode " << i + 1;
    EXPECT_EQ(s.modes[i].radial, modes[i].radial) << "mode " << i + 1;
  }
}

// An independent computation: the mesh method (gmsh triangles, survey + clusters) on a structured P6 mesh
// gives the same 8 largest modes.
TEST(SeparableCylinder, AgreesWithTheMeshMethod) {
  auto sep = separable_request(1.0, 2.0, 8);
  sep.check_convergence = false;
  auto mesh = sep;
  mesh.method = TableMethod::mesh;
  mesh.mesh.order = 6;
  mesh.mesh.size = 0.5;
  mesh.mesh.radial_size = 1.0 / 16;
  const auto a = compute_mode_table(sep), b = compute_mode_table(mesh);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), 8u);
  double worst = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    worst = std::max({worst, rel(b.kappa[i], a.kappa[i]), rel(b.E[i], a.E[i])});
    EXPECT_LE(rel(b.kappa[i], a.kappa[i]), 1e-6) << "row " << i + 1;
    EXPECT_LE(rel(b.E[i], a.E[i]), 1e-6) << "row " << i + 1;
  }
  EXPECT_LE(rel(b.J_zh, a.J_zh), 1e-6);
  std::printf("separable (%.3f s) vs mesh (%.2f s): 8 largest modes agree to %.2e, J_zh to %.2e\n", a.wall_seconds,
              b.wall_seconds, worst, rel(b.J_zh, a.J_zh));
}

TEST(SeparableCylinder, RefusesOtherShapesAndBadGrids) {
  const rc::geometry::MeshOptions defaults{0, 0, 0};
  EXPECT_THROW(separable_grid({"sphere", {{"radius", 1.0}}, {}}, defaults), std::runtime_error);
  EXPECT_THROW(separable_grid({"cylinder", {{"radius", 1.0}, {"height", -1.0}}, {}}, defaults), std::runtime_error);
  EXPECT_THROW(separable_grid({"cylinder", {{"radius", 1.0}, {"height", 1.0}}, {}}, {13, 0, 0}), std::runtime_error);
  EXPECT_THROW(separable_grid({"cylinder", {{"radius", 1.0}, {"height", 1.0}}, {}}, {8, NAN, 0}), std::runtime_error);
}
