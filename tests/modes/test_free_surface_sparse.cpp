// The sparse free-surface solver (modes/freesurface/free_surface_sparse.hpp): SLEPc's pairs near given frequencies
// against the dense solver's on the same mesh, and on a mesh beyond the dense solver's reach against Stewartson's
// closed form and the sphere's rigid turn. Every comparison prints its error.
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "free_surface_mesh.hpp"
#include "free_surface_sparse.hpp"
#include "partial_fill_table.hpp"
#include "partial_fill_closed_form.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace rc;
using namespace rc::modes;

namespace {

FESpace liquid_space(const geometry::ShapeSpec& shape, double fill, int order, double size) {
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  return FESpace(geometry::mesh_meridian(geometry::partially_filled(shape, fill), o));
}

const PartialFillPair& nearest(const PartialFillSpectrum& s, double lambda) {
  const PartialFillPair* best = &s.pairs.front();
  for (const auto& p : s.pairs)
    if (std::abs(p.lambda - lambda) < std::abs(best->lambda - lambda)) best = &p;
  return *best;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

// Fill 0.9 cylinder, 2h/a = 2, P6 at h = 0.5: the dense solver's four heaviest pairs, each found again by SLEPc at its
// own λ, agree in λ, E and t.
TEST(FreeSurfaceSparse, SamePairsAsTheDenseSolver) {
  const geometry::ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  const FESpace space = liquid_space(cylinder, 0.9, 6, 0.5);
  const PartialFillSpectrum dense = solve_partially_filled_mesh(space, 4000);
  std::vector<double> targets;
  for (int k = 0; k < 4; ++k) targets.push_back(dense.pairs[k].lambda + 1e-3);
  const PartialFillSpectrum sparse = solve_partially_filled_near(space, targets, 2);
  EXPECT_NEAR(sparse.sum_rule, dense.sum_rule, 1e-14 * dense.sum_rule);
  for (int k = 0; k < 4; ++k) {
    const PartialFillPair& d = dense.pairs[k];
    const PartialFillPair& s = nearest(sparse, d.lambda);
    std::printf("lambda %.14f (dense %.14f, %.1e), E %.12g (%.1e), |t| %.3g (%.3g), residual %.1e\n", s.lambda,
                d.lambda, std::abs(s.lambda - d.lambda), s.coupling.E, std::abs(s.coupling.E / d.coupling.E - 1),
                std::abs(s.coupling.t), std::abs(d.coupling.t), s.residual);
    EXPECT_NEAR(s.lambda, d.lambda, 1e-11);
    EXPECT_NEAR(s.coupling.E, d.coupling.E, 1e-9 * d.coupling.E);
    EXPECT_NEAR(std::abs(s.coupling.t), std::abs(d.coupling.t), 1e-9 * std::abs(d.coupling.a));
    EXPECT_LT(s.residual, 1e-10);
  }
}

// Beyond the dense solver of a table (P6 at h = 0.12, 4742 unknowns): the fill 0.9 cylinder's heaviest frequencies against
// Stewartson's closed form, and the partially filled sphere's rigid turn (λ = 1, E = A_f + K2) at fill 0.4.
TEST(FreeSurfaceSparse, FineMeshesAgainstClosedForms) {
  const geometry::ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  const auto start = std::chrono::steady_clock::now();
  const FESpace space = liquid_space(cylinder, 0.9, 6, 0.12);
  const auto exact = exact::partially_filled_cylinder_modes(1.0, 2.0, 0.9);
  const double lambdas[3] = {0.982868976888, 0.514967027541, -0.520663095928};
  const PartialFillSpectrum s = solve_partially_filled_near(space, {lambdas[0], lambdas[1], lambdas[2]}, 3);
  std::printf("cylinder: %ld unknowns, %zu pairs in %.1f s\n", free_surface_unknowns(space), s.pairs.size(),
              seconds_since(start));
  EXPECT_GT(free_surface_unknowns(space), kDenseFreeSurfaceUnknowns);
  for (const double l : lambdas) {
    double closed = 1e300;
    for (const auto& m : exact)
      if (std::abs(m.lambda - l) < std::abs(closed - l)) closed = m.lambda;
    const PartialFillPair& p = nearest(s, closed);
    std::printf("  lambda %.13f (closed form %.13f, %.1e), E %.10g\n", p.lambda, closed, std::abs(p.lambda - closed),
                p.coupling.E);
    EXPECT_NEAR(p.lambda, closed, 1e-10);
  }
  const geometry::ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  const FESpace ball = liquid_space(sphere, 0.4, 6, 0.06);
  const PartialFillSpectrum t = solve_partially_filled_near(ball, {1.0 + 1e-3}, 12);
  const PartialFillPair& turn = nearest(t, 1.0);
  const double rule = t.fluid.A_f + t.K2;
  std::printf("sphere: %ld unknowns; lambda %.14f (1: %.1e), E %.12g = A_f + K2 %.12g (%.1e), J_D %.1e\n",
              free_surface_unknowns(ball), turn.lambda, std::abs(turn.lambda - 1), turn.coupling.E, rule,
              std::abs(turn.coupling.E / rule - 1), t.J_D);
  EXPECT_GT(free_surface_unknowns(ball), kDenseFreeSurfaceUnknowns);
  EXPECT_NEAR(turn.lambda, 1.0, 1e-11);
  EXPECT_NEAR(turn.coupling.E, rule, 1e-9 * rule);
}

// The table on two levels (partial_fill_table.hpp): with the dense solver's limit set below the mesh, the rows come
// from the sparse solver at the targets of the mesh with its sizes doubled; they are the dense table's rows on the
// same mesh (fill 0.9 cylinder, P6 at h = 0.3), its convergence check unchanged.
TEST(FreeSurfaceSparse, TwoLevelTableIsTheDenseTable) {
  PartialFillTableSettings req;
  req.shape = {"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  req.grid.order = 6;
  req.grid.size = 0.3;
  req.fill = 0.9;
  req.selection.modes = 8;
  const ModeTable dense = partially_filled_mesh_table(req, nullptr);
  const long unknowns = free_surface_unknowns(liquid_space(req.shape, req.fill, 6, 0.3));
  req.max_unknowns = static_cast<int>(unknowns) - 1;  // the fine mesh only goes past it
  const ModeTable sparse = partially_filled_mesh_table(req, [](const std::string& line) { std::printf("  %s\n", line.c_str()); });
  std::printf("%ld unknowns; %zu rows (dense %zu); coverage %.10f (dense %.10f)\n", unknowns, sparse.size(), dense.size(),
              sparse.coverage, dense.coverage);
  ASSERT_EQ(sparse.size(), dense.size());
  for (std::size_t k = 0; k < dense.size(); ++k) {
    std::printf("  lambda %.13f (dense %.1e), E %.10g (%.1e of the sum rule), converged %d (%d)\n", sparse.lambda[k],
                std::abs(sparse.lambda[k] - dense.lambda[k]), sparse.E[k], std::abs(sparse.E[k] - dense.E[k]) / dense.sum_rule,
                sparse.converged[k], dense.converged[k]);
    EXPECT_NEAR(sparse.lambda[k], dense.lambda[k], 1e-11);
    EXPECT_NEAR(sparse.E[k], dense.E[k], 1e-9 * dense.sum_rule);  // some rows are kept for t, their E at rounding
    EXPECT_EQ(sparse.converged[k], dense.converged[k]);
  }
  EXPECT_NEAR(sparse.coverage, dense.coverage, 1e-9);
}
