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
  modes::FESpace space(geometry::mesh_meridian(kAnnulus, {3, 0.5}));
  const auto fluid = modes::integrate_fluid(space);
  const auto forms = modes::assemble_poincare_forms(space, fluid.centroid_z);
  const modes::StiffnessSolver stiffness(forms.M);
  const auto zh = modes::zhukovsky_inertia(forms, stiffness);
  const auto all = modes::QuadraticEigenSolver(forms, {}).solve_all_dense();
  double sum = 0;
  for (const auto& p : all.pairs) sum += p.coupling.E;
  const double rule = fluid.A_f - zh.J_zh, err = std::abs(sum - rule) / rule;
  std::printf("annulus P3 h = 0.5, %d dofs: sum E %.15g, A_f - J_zh %.15g, relative %.1e\n", space.ndof(), sum, rule,
              err);
  EXPECT_LT(err, 1e-10);
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
