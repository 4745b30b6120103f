// Cavities that do not touch the axis (docs/geometry.md, "Sections"): the annular cylinder of
// data/sections/annulus.geo (rod 0.3, radius 1, height 2; no "axis" group) by the mesh method against its separable
// closed form (closed_forms.hpp: F = J1 + c Y1 with both walls' conditions), its sum rule on every eigenpair, and a
// section that reaches r = 0 without an axis group refused with one line.
#include "cavity_table.hpp"
#include "closed_forms.hpp"
#include "fe_space.hpp"
#include "poincare_forms.hpp"
#include "qep_solver.hpp"
#include "stiffness_solver.hpp"
#include "zhukovsky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace rc;

namespace {

const geometry::ShapeSpec kAnnulus{"section", {}, std::filesystem::path(RC_SECTIONS_DIR) / "annulus.geo"};

// Σ E over every eigenpair of the dense QEP against A_f − J_zh of the same discretisation, relative; prints both.
double sum_rule_error(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh, const char* name) {
  modes::FESpace space(geometry::mesh_meridian(shape, mesh));
  const auto fluid = modes::integrate_fluid(space);
  const auto forms = modes::assemble_poincare_forms(space, fluid.centroid_z);
  const modes::StiffnessSolver stiffness(forms.M);
  const auto zh = modes::zhukovsky_inertia(forms, stiffness);
  const auto all = modes::QuadraticEigenSolver(forms, {}).solve_all_dense();
  double sum = 0;
  for (const auto& p : all.pairs) sum += p.coupling.E;
  const double rule = fluid.A_f - zh.J_zh, err = std::abs(sum - rule) / rule;
  std::printf("%s P%d h = %g, %d dofs: sum E %.15g, A_f - J_zh %.15g, relative %.1e\n", name, mesh.order, mesh.size,
              space.ndof(), sum, rule, err);
  return err;
}

}  // namespace

// The table's four leading modes (order 6, the default mesh) against the closed form's, matched by κ: κ to 1e-9 and
// E to 1e-6 relative (the table's own convergence check estimates 1e-12 and 1e-7).
TEST(AnnularCylinder, MeshTableIsTheSeparableClosedForm) {
  modes::TableRequest req;
  req.shape = kAnnulus;
  req.mesh.order = 6;
  req.selection.modes = 4;
  req.check_convergence = false;
  const ModeTable t = modes::compute_mode_table(req);
  const auto exact = modes::exact::annular_cylinder_modes(0.3, 1.0, 2.0, 4, 40.0);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const modes::exact::Mode* best = nullptr;
    for (const auto& m : exact)
      if (!best || std::abs(m.kappa - t.kappa[i]) < std::abs(best->kappa - t.kappa[i])) best = &m;
    const double dk = std::abs(t.kappa[i] - best->kappa) / std::abs(best->kappa), dE = std::abs(t.E[i] - best->E) / best->E;
    std::printf("mode %zu: table kappa %.12f E %.10f; closed form (n = %d, j = %d) kappa %.12f E %.10f; errors %.1e, "
                "%.1e\n", i + 1, t.kappa[i], t.E[i], best->axial, best->radial, best->kappa, best->E, dk, dE);
    EXPECT_LT(dk, 1e-9);
    EXPECT_LT(dE, 1e-6);
  }
}

// Σ E over every eigenpair = A_f − J_zh: on straight-sided elements an exact discrete identity (docs/physics.md §2),
// with the rod's wall where the axis was.
TEST(AnnularCylinder, SumRuleOverEveryEigenpair) {
  EXPECT_LT(sum_rule_error(kAnnulus, {3, 0.5}, "annulus"), 1e-10);
}

// A section that reaches r = 0 but has no "axis" group: refused with one line (the m = 1 fields need the axis
// conditions there), not meshed into a wrong table.
TEST(AnnularCylinder, SectionOnTheAxisWithoutAxisGroupIsRefused) {
  const auto file = std::filesystem::temp_directory_path() / "rc_no_axis_test.geo";
  std::ofstream(file) << "Point(1) = {0, -1, 0, 0.5}; Point(2) = {1, -1, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};\n"
                         "Point(4) = {0, 1, 0, 0.5};\nLine(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; "
                         "Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                         "Physical Surface(\"fluid\") = {1}; Physical Curve(\"wall\") = {1, 2, 3, 4};\n";
  try {
    geometry::mesh_meridian({"section", {}, file}, {3, 0.5});
    ADD_FAILURE() << "a section on the axis without an axis group was meshed";
  } catch (const std::runtime_error& e) {
    std::printf("refused: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("no 1D physical group named 'axis'"), std::string::npos);
  }
  std::filesystem::remove(file);
}

// A torus (data/sections/torus.geo: a tube of radius 0.4 around the circle of radius 1; no axis, a curved wall and no
// closed form for its modes). Its frozen-fluid integrals converge to the exact ones (volume 2π²Ra², A_f =
// m(R²/2 + 5a²/8), C_f = m(R² + 3a²/4)) as the curved wall does; Σ E over every eigenpair approaches A_f − J_zh as
// the curved wall's geometry converges; and its leading modes agree between two meshes (the table's own flags).
TEST(RingSections, TorusIntegralsSumRuleAndLeadingModes) {
  const geometry::ShapeSpec torus{"section", {}, std::filesystem::path(RC_SECTIONS_DIR) / "torus.geo"};
  const double R = 1.0, a = 0.4, pi = 3.14159265358979323846;
  const double m = 2 * pi * pi * R * a * a;
  modes::FESpace fine(geometry::mesh_meridian(torus, {6, 0.1}));
  const auto f = modes::integrate_fluid(fine);
  const double dV = std::abs(f.volume - m) / m, dA = std::abs(f.A_f - m * (R * R / 2 + 5 * a * a / 8)) / f.A_f,
               dC = std::abs(f.C_f - m * (R * R + 0.75 * a * a)) / f.C_f;
  std::printf("torus P6 h = 0.1: volume %.2e, A_f %.2e, C_f %.2e relative to the exact integrals; centroid z %.1e\n", dV,
              dA, dC, f.centroid_z);
  EXPECT_LT(std::max({dV, dA, dC}), 1e-8);
  EXPECT_LT(std::abs(f.centroid_z), 1e-12);

  // The identity is exact on straight-sided elements (the annulus above); the torus's wall is curved, and its
  // isoparametric elements leave the sum rule off by the geometry's discretisation error, which falls with the order.
  const double p3 = sum_rule_error(torus, {3, 0.2}, "torus"), p4 = sum_rule_error(torus, {4, 0.2}, "torus");
  EXPECT_LT(p4, 0.1 * p3);
  EXPECT_LT(p4, 1e-7);

  modes::TableRequest req;
  req.shape = torus;
  req.mesh.order = 6;
  req.selection.modes = 4;
  const ModeTable t = modes::compute_mode_table(req);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t i = 0; i < t.size(); ++i)
    std::printf("torus mode %zu: kappa %.10f E %.8e (dlambda %.1e, dE %.1e: %s)\n", i + 1, t.kappa[i], t.E[i],
                t.dlambda[i], t.dE[i], t.converged[i] ? "converged" : "NOT converged");
  std::printf("torus: J_zh %.10f, A_f %.10f, coverage of the 4 modes %.4f\n", t.J_zh, t.A_f, t.coverage);
  EXPECT_TRUE(t.converged[0]);  // the dominant mode: a torus is a smooth cavity (docs/trust.md, "Ring-shaped tanks")
}
