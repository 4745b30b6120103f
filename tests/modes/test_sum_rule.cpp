// Completeness: on a small mesh with every eigenpair computed, Σ E = A_f − J_zh (docs/physics.md §2).
// On straight-sided meshes (cylinder) it is an exact discrete identity: e1 × r is then a combination of
// discrete gradients and their Coriolis images. On curved isoparametric meshes it holds up to the
// geometry error, which falls fast with the order (measured on the spheroid c/a = 2: P3 h = 0.5 7.2e-7,
// P6 h = 1 1.8e-9, P6 h = 0.5 1.5e-11).
// It also checks that E stays finite and bounded on the λ ≈ 0 geostrophic cluster.
#include "fe_space.hpp"
#include "poincare_forms.hpp"
#include "qep_solver.hpp"
#include "stiffness_solver.hpp"
#include "window_weight.hpp"
#include "zhukovsky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace rc;

namespace {

void check_sum_rule(const geometry::ShapeSpec& shape, int order, double size, double tolerance) {
  modes::FESpace space(geometry::mesh_meridian(shape, {order, size}));
  const auto fluid = modes::integrate_fluid(space);
  const auto forms = modes::assemble_poincare_forms(space, fluid.centroid_z);
  const modes::StiffnessSolver stiffness(forms.M);
  const auto zh = modes::zhukovsky_inertia(forms, stiffness);
  const auto all = modes::QuadraticEigenSolver(forms, {}).solve_all_dense();
  ASSERT_EQ(all.pairs.size(), 2u * space.ndof());
  double sum = 0, near_zero = 0;
  for (const auto& p : all.pairs) {
    ASSERT_TRUE(std::isfinite(p.coupling.E)) << "lambda " << p.lambda;
    ASSERT_GE(p.coupling.E, 0.0);
    ASSERT_LE(std::abs(p.lambda), 2.0 + 1e-10);  // |λ| = 2 (D = 0) occurs discretely: E stays finite there
    sum += p.coupling.E;
    if (std::abs(p.lambda) < 1e-3) near_zero += p.coupling.E;
  }
  const double rule = fluid.A_f - zh.J_zh, err = std::abs(sum - rule) / rule;
  std::printf("%s order %d: %d dofs, %zu eigenpairs, sum E %.15g, A_f - J_zh %.15g, rel err %.2e, "
              "E in |lambda| < 1e-3: %.3e\n",
              shape.kind.c_str(), order, space.ndof(), all.pairs.size(), sum, rule, err, near_zero);
  EXPECT_LE(err, tolerance);
  EXPECT_LE(near_zero, rule);
}

}  // namespace

TEST(SumRule, ExactOnStraightSidedMesh) {
  check_sum_rule({"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}}, 4, 0.5, 1e-12);
}

TEST(SumRule, CurvedMeshToGeometryError) {
  check_sum_rule({"spheroid", {{"a", 1.0}, {"c", 2.0}}, {}}, 6, 1.0, 1e-8);
}

// spectral-window's exact band weight (SLEPc spectrum slicing of one window) against the sum of E over the same
// window of EVERY eigenpair (the dense solve), on a user section: the capsule of data/sections, order 3, h = 0.5.
TEST(SumRule, WindowWeightIsTheSumOverEveryEigenpairInTheWindow) {
  const geometry::ShapeSpec capsule{"section", {}, std::filesystem::path(RC_SECTIONS_DIR) / "capsule.geo"};
  modes::FESpace space(geometry::mesh_meridian(capsule, {3, 0.5}));
  const auto fluid = modes::integrate_fluid(space);
  const auto forms = modes::assemble_poincare_forms(space, fluid.centroid_z);
  const modes::QuadraticEigenSolver solver(forms, {});
  const auto all = solver.solve_all_dense();
  for (const auto& [lo, hi] : {std::pair{0.4, 0.5}, std::pair{-0.5, -0.2}, std::pair{1.0, 1.9}}) {
    double dense = 0;
    std::size_t pairs = 0;
    for (const auto& p : all.pairs)
      if (p.lambda >= lo && p.lambda < hi) { dense += p.coupling.E; ++pairs; }
    const auto w = modes::weigh_window(solver, lo, hi);
    const double err = std::abs(w.E - dense) / dense;
    std::printf("capsule P3 h = 0.5, %d dofs, window [%g, %g): %zu pairs (dense %zu), E %.15g, dense %.15g, "
                "rel err %.2e\n", space.ndof(), lo, hi, w.pairs, pairs, w.E, dense, err);
    EXPECT_EQ(w.pairs, pairs);
    EXPECT_LE(err, 1e-10);
  }
}
