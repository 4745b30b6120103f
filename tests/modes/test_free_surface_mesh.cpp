// A partially filled tank by the mesh method (modes/freesurface/free_surface_mesh.hpp): the partially filled cylinder
// on a triangle mesh against Stewartson's closed form (partial_fill_closed_form.hpp) and the separated solver's
// couplings (partial_fill_cylinder.hpp), and the sum rule Σ E = A_f(O) + K(O) − J_D(O) for shapes without a closed
// form (sphere, cone). Every comparison prints its error.
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "free_surface_mesh.hpp"
#include "partial_fill_table.hpp"
#include "partial_fill_closed_form.hpp"
#include "partial_fill_cylinder.hpp"
#include "separable_cylinder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace rc;
using namespace rc::modes;

namespace {

PartialFillSpectrum mesh_spectrum(const geometry::ShapeSpec& shape, double fill, int order, double size,
                                  double radial_size = 0) {
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  o.radial_size = radial_size;
  return solve_partially_filled_mesh(FESpace(geometry::mesh_meridian(geometry::partially_filled(shape, fill), o)),
                                     4000);
}

// The pair nearest λ among those at least `floor` heavy.
const PartialFillPair& nearest(const PartialFillSpectrum& s, double lambda, double floor) {
  const PartialFillPair* best = nullptr;
  for (const auto& p : s.pairs)
    if (p.coupling.E >= floor && (!best || std::abs(p.lambda - lambda) < std::abs(best->lambda - lambda))) best = &p;
  return *best;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

// Fill 0.9, 2h/a = 2: the heavy modes' λ against the closed form, their E, t against the separated solver, and the
// complete spectrum's Σ E against the sum rule about the centroid and two other points.
TEST(FreeSurfaceMesh, CylinderIsStewartsonsClosedForm) {
  const double fill = 0.9, height = 2;
  const geometry::ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", height}}, {}};
  const PartialFillSpectrum s = mesh_spectrum(cylinder, fill, 6, 0.5, 0.25);
  const auto exact = exact::partially_filled_cylinder_modes(1.0, height, fill);
  const double b = exact::partial_fill_surface_radius(1.0, fill);
  const PartialFillSpectrum sep =
      solve_partially_filled_cylinder(1.0, height, fill, SeparableGrid::graded(1.0, height, 8, 6, 12, 2, b));
  std::printf("mesh: %d dofs, %zu pairs, sum E = %.12g, sum rule = %.12g (relative %.1e)\n", s.radial_dofs,
              s.pairs.size(), s.sum_E, s.sum_rule, relative(s.sum_E, s.sum_rule));
  EXPECT_LT(relative(s.sum_E, s.sum_rule), 1e-9);
  for (const double c : {0.7, -1.3}) {
    double sum = 0;
    for (const auto& p : s.pairs) sum += coupling_about(p.coupling, c);
    std::printf("  about c = %+.1f: sum E = %.12g, rule %.12g (relative %.1e)\n", c, sum, s.sum_rule_about(c),
                relative(sum, s.sum_rule_about(c)));
    EXPECT_LT(relative(sum, s.sum_rule_about(c)), 1e-9);
  }
  std::printf("  J_D %.12g (separated %.12g, %.1e), K2 %.12g (%.12g)\n", s.J_D, sep.J_D, relative(s.J_D, sep.J_D),
              s.K2, sep.K2);
  // The potential vanishes on the free surface and not on the lids it meets: a corner singularity that the separated
  // grid grades towards and this uniform mesh does not.
  EXPECT_LT(relative(s.J_D, sep.J_D), 1e-4);
  EXPECT_LT(relative(s.K2, sep.K2), 1e-12);
  // The three heaviest separated pairs, each against its mesh pair and the closed form.
  for (int k = 0; k < 3; ++k) {
    const PartialFillPair& ref = sep.pairs[k];
    const PartialFillPair& got = nearest(s, ref.lambda, 0.1 * ref.coupling.E);
    double closed = 1e300;
    for (const auto& m : exact)
      if (std::abs(m.lambda - ref.lambda) < std::abs(closed - ref.lambda)) closed = m.lambda;
    std::printf("  lambda %.12f (closed form %.12f, %.1e), E %.10g (separated %.10g, %.1e), t %.10g (%.10g)\n",
                got.lambda, closed, relative(got.lambda, closed), got.coupling.E, ref.coupling.E,
                relative(got.coupling.E, ref.coupling.E), std::abs(got.coupling.t), std::abs(ref.coupling.t));
    EXPECT_LT(relative(got.lambda, closed), 1e-8);
    EXPECT_LT(relative(got.coupling.E, ref.coupling.E), 1e-6);
    // t = 0 for these: p is odd in z about the centroid (the sums about c = 0.7 and −1.3 above check t in general).
    EXPECT_LT(std::abs(std::abs(got.coupling.t) - std::abs(ref.coupling.t)), 1e-9 * std::abs(ref.coupling.a));
  }
}

// A sphere's liquid may turn rigidly about a tilted axis, its free surface the cylinder r = b about that axis: an
// exact steady solution whatever the fill, seen in the body frame at λ = 1. It is the only coupled mode: the walls
// are invariant under the tilt, so Zhukovsky's potential vanishes (J_D = 0) and Σ E = A_f + K2 sits on it. A_f, K2 in
// closed form for the liquid b < r, r² + z² < 1 (u = √(1 − b²)): A_f = π ∫∫ (r² + 2z²) r dr dz, K2 = (2/3)π b² u³.
TEST(FreeSurfaceMesh, SphereTurnsRigidlyAboutATiltedAxis) {
  const geometry::ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  for (const auto& [fill, size] : {std::pair{0.4, 0.2}, std::pair{0.8, 0.3}}) {
    const PartialFillSpectrum s = mesh_spectrum(sphere, fill, 6, size);
    const double b = s.surface_radius, u = std::sqrt(1 - b * b), pi = std::acos(-1.0);
    // ∫_{-u}^{u} ∫_b^{√(1−z²)} (r² + 2z²) r dr dz = ∫ [((1 − z²)² − b⁴)/4 + z²(1 − z² − b²)] dz.
    const double A_f = pi * (0.5 * (u - 2 * u * u * u / 3 + u * u * u * u * u / 5) - 0.5 * b * b * b * b * u +
                             2 * ((1 - b * b) * u * u * u / 3 - u * u * u * u * u / 5));
    const double K2 = 2 * pi * b * b * u * u * u / 3;
    const PartialFillPair& top = s.pairs.front();
    std::printf("fill %.1f: b = %.10f, %d dofs; lambda %.14f (1: %.1e), E %.12g = A_f + K2 %.12g (%.1e), next E %.1e, "
                "J_D %.1e, A_f %.12g (closed form %.1e)\n", fill, b, s.radial_dofs, top.lambda, std::abs(top.lambda - 1),
                top.coupling.E, A_f + K2, relative(top.coupling.E, A_f + K2), s.pairs[1].coupling.E, s.J_D,
                s.fluid.A_f, relative(s.fluid.A_f, A_f));
    EXPECT_NEAR(top.lambda, 1.0, 1e-11);
    EXPECT_LT(relative(top.coupling.E, A_f + K2), 1e-9);
    EXPECT_LT(relative(s.K2, K2), 1e-12);
    EXPECT_LT(s.pairs[1].coupling.E, 1e-9 * top.coupling.E);  // rounding of the dense solve: measured ≤ 1.5e-10
    EXPECT_LT(std::abs(s.J_D), 1e-12);
  }
}

// The fields of the same rigid turn (cavity-modes --fill --fields): V = C (z, −z, −r) in the table's real amplitudes
// (V = (i v_r, v_φ, i v_z) e^{iφ}: the rotation e1 × r about the sphere's centre), p = −C r z and on the free surface
// η = −p/b = C z, with C = 1/√(2(A_f + K2)) from ‖W‖² = ∫|V|² + b∫|η|² = 2C²A_f + 2C²K2 = 1. The pressure is a
// polynomial the P6 space holds, so the nodal fields match it to rounding but for the curved wall's geometry. The sign
// is the filled sphere's spin-over field's (measured: +C (z, −z, −r) there too), so fields stay continuous as F → 1.
TEST(FreeSurfaceMesh, FieldsOfTheRigidTurnAreTheClosedForm) {
  const geometry::ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  PartialFillTableSettings settings;
  settings.shape = sphere;
  settings.fill = 0.4;
  settings.grid.order = 6;
  settings.grid.size = 0.2;
  settings.check_convergence = false;
  ModeFields fields;
  const ModeTable t = partially_filled_mesh_table(settings, {}, &fields);
  ASSERT_EQ(fields.modes.size(), t.size());
  ASSERT_NEAR(t.lambda[0], 1.0, 1e-11);
  const double scale = 1 / std::sqrt(2 * t.E[0]);  // C of the header: the row's E is A_f + K2 (the test above)
  const ModeFields::Mode& m = fields.modes[0];
  double worst_v = 0, worst_p = 0, big = 0;
  for (std::size_t i = 0; i < fields.num_points(); ++i) {
    const double r = fields.points[3 * i], z = fields.points[3 * i + 2];
    const double exact[3] = {scale * z, -scale * z, -scale * r};
    for (int k = 0; k < 3; ++k) worst_v = std::max(worst_v, std::abs(m.V[3 * i + k] - exact[k]));
    worst_p = std::max(worst_p, std::abs(m.p[i] + scale * r * z));
    big = std::max(big, scale * std::max(std::abs(z), r));
  }
  std::printf("fill 0.4: rigid turn's fields at %zu nodes: V to %.1e, p to %.1e of max|V| = %.4f; stored a %.12g = "
              "sqrt(E/2) %.12g\n", fields.num_points(), worst_v / big, worst_p / big, big, m.a, std::sqrt(t.E[0] / 2));
  EXPECT_LT(worst_v / big, 3e-6);  // measured 3.2e-7 (nodal gradients at the curved wall)
  EXPECT_LT(worst_p / big, 1e-7);  // measured 4.1e-9
  EXPECT_NEAR(m.a, std::sqrt(t.E[0] / 2), 1e-12);
}

// A cone (apex down) cut by its free surface: no closed form, so the complete spectrum's Σ E against the sum rule
// about the centroid and two other points, which uses J_D(O) of a separate potential solve.
TEST(FreeSurfaceMesh, ConeSumRuleAboutThreePoints) {
  const geometry::ShapeSpec cone{"cone", {{"radius", 1.0}, {"height", 2.0}}, {}};
  const PartialFillSpectrum s = mesh_spectrum(cone, 0.7, 5, 0.25);
  for (const double c : {0.0, 0.9, -1.4}) {
    double sum = 0;
    for (const auto& p : s.pairs) sum += coupling_about(p.coupling, c);
    std::printf("cone fill 0.7, %d dofs, about c = %+.1f: sum E = %.12g, A_f(O) + K(O) - J_D(O) = %.12g (%.1e)\n",
                s.radial_dofs, c, sum, s.sum_rule_about(c), relative(sum, s.sum_rule_about(c)));
    EXPECT_LT(relative(sum, s.sum_rule_about(c)), 1e-9);
  }
}

// Stewartson's frequencies (docs/physics.md §2's table: the first axial wave's modes with |λ| > 0.45) among the mesh
// method's eigenvalues at its defaults (order 6, 3.5 × geometry's default size), for two of the table's cases (fill 0.98,
// 2h/a = 3, 1075 dofs, measured 1.1e-7: docs/modes.md, "Partially filled tanks").
TEST(FreeSurfaceMesh, DefaultMeshGivesStewartsonsFrequencies) {
  for (const auto& [fill, height] : {std::pair{0.8, 1.0}, std::pair{0.9, 2.0}}) {
    const geometry::ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", height}}, {}};
    const geometry::ShapeSpec liquid = geometry::partially_filled(cylinder, fill);
    const PartialFillSpectrum s = mesh_spectrum(cylinder, fill, 6, 3.5 * geometry::default_mesh_size(liquid));
    double worst = 0;
    int count = 0;
    for (const auto& m : exact::partially_filled_cylinder_modes(1.0, height, fill)) {
      if (m.axial != 0 || std::abs(m.lambda) <= 0.45) continue;
      double best = 1e300;
      for (const auto& p : s.pairs) best = std::min(best, relative(p.lambda, m.lambda));
      worst = std::max(worst, best);
      ++count;
    }
    std::printf("fill %.2f, 2h/a = %.0f: %d dofs, %d closed-form frequencies, worst relative distance %.1e\n", fill,
                height, s.radial_dofs, count, worst);
    EXPECT_GT(count, 1);
    EXPECT_LT(worst, 1e-8);
  }
}

// A partly filled payload around a burster tube: the fill counts the volume between rod and wall, and the liquid
// (b < r < a, b² = a² − F(a² − r_i²)) does not reach the rod. So the mesh method's table of the cylinder with a rod of
// radius 0.3 filled to 0.95 is the plain cylinder's filled to 1 − b², here by the separated solver.
TEST(FreeSurfaceMesh, RodBelowTheSurfaceTakesNoPart) {
  const geometry::ShapeSpec rod{"cylinder", {{"radius", 1.0}, {"height", 2.0}, {"inner_radius", 0.3}}, {}};
  const PartialFillSpectrum s = mesh_spectrum(rod, 0.95, 6, 0.5, 0.25);
  const double b = s.surface_radius, plain_fill = 1 - b * b;
  std::printf("rod 0.3, fill 0.95: b = %.12f (closed form %.12f); the plain cylinder's fill %.10f\n", b,
              std::sqrt(1 - 0.95 * (1 - 0.09)), plain_fill);
  EXPECT_NEAR(b, std::sqrt(1 - 0.95 * (1 - 0.09)), 1e-14);
  const PartialFillSpectrum sep = solve_partially_filled_cylinder(
      1.0, 2.0, plain_fill, SeparableGrid::graded(1.0, 2.0, 8, 6, 12, 2, exact::partial_fill_surface_radius(1.0, plain_fill)));
  for (int k = 0; k < 3; ++k) {
    const PartialFillPair& ref = sep.pairs[k];
    const PartialFillPair& got = nearest(s, ref.lambda, 0.1 * ref.coupling.E);
    std::printf("  lambda %.12f (plain cylinder %.12f, %.1e), E %.10g (%.10g, %.1e)\n", got.lambda, ref.lambda,
                relative(got.lambda, ref.lambda), got.coupling.E, ref.coupling.E, relative(got.coupling.E, ref.coupling.E));
    EXPECT_LT(relative(got.lambda, ref.lambda), 1e-9);
    EXPECT_LT(relative(got.coupling.E, ref.coupling.E), 1e-6);
  }
}
