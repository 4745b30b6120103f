// A partially filled 3-D tank, on or off the craft's spin axis (docs/volume.md §8): the liquid's cut against the
// sphere's closed form, the free-surface operator's symmetry, and on the axis — where the meridian solver
// (modes/freesurface/) is an independent computation — the sphere's rigid turn in closed form and a spheroid's modes.
#include "free_surface_mesh.hpp"
#include "free_surface_survey.hpp"
#include "meridian_mesh.hpp"
#include "partial_volume.hpp"
#include "volume_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

using namespace rc;
using namespace rc::modes;

namespace {

geometry::VolumeMesh tank(double a, double c, double fill, std::array<double, 2> spin_axis, int order, double size) {
  geometry::VolumeShapeSpec shape;
  shape.kind = "ellipsoid";
  shape.dims = {{"a", a}, {"b", a}, {"c", c}};
  shape.fill = fill;
  shape.spin_axis = spin_axis;
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  return geometry::mesh_volume(shape, o);
}

struct Liquid {
  VolumeSpace space;
  VolumeForms forms;
  FreeSurfaceDynamics A;
  explicit Liquid(geometry::VolumeMesh m)
      : space(std::move(m), 0, false), forms(assemble_volume_forms(space)), A(space, forms) {}
};

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

// The sphere's liquid beyond the cylinder ρ = b about its own axis fills (1 − b²)^{3/2} of it, a spheroid's (scaled along
// its axis) the same.
TEST(OffAxisFill, SphereSurfaceRadiusIsTheClosedForm) {
  const double fill = 0.6;
  const auto m = tank(1, 1, fill, {0, 0}, 3, 0.4);
  const double b = std::sqrt(1 - std::pow(fill, 2.0 / 3.0));
  std::printf("fill %.1f on the axis: b = %.12f, closed form %.12f (%.1e)\n", fill, m.free_surface_radius, b,
              std::abs(m.free_surface_radius - b));
  EXPECT_NEAR(m.free_surface_radius, b, 1e-9);
  // A spheroid's liquid beyond the coaxial cylinder fills the same fraction whatever c: oblate and prolate revolved alike.
  for (const double c : {0.8, 1.5}) {
    const double bc = tank(1, c, fill, {0, 0}, 2, 0.5).free_surface_radius;
    std::printf("spheroid c = %.1f: b = %.12f (%.1e)\n", c, bc, std::abs(bc - b));
    EXPECT_NEAR(bc, b, 1e-9);
  }
  // Off the axis (the axis 2 from the centre, outside the tank): the meshed liquid's volume is the fill's.
  const auto off = tank(1, 1, fill, {-2, 0}, 4, 0.3);
  const double volume = integrate_volume(VolumeSpace(off, 0, false)).volume, want = fill * 4 * std::numbers::pi / 3;
  std::printf("fill %.1f, axis 2 off the centre: b = %.10f, meshed volume %.10f, fill x sphere %.10f (%.1e)\n", fill,
              off.free_surface_radius, volume, want, relative(volume, want));
  EXPECT_LT(relative(volume, want), 3e-6);  // measured 8.0e-7 (P4, h 0.3)
  EXPECT_GT(off.free_surface_radius, 1.0);  // beyond the centre: more than half the sphere lies outside ρ = 2
}

// ⟨x, A y⟩ = ⟨A x, y⟩ on states of the invariant space (the images of random states), whose surface mean stays zero.
TEST(OffAxisFill, OperatorIsSelfAdjoint) {
  Liquid l(tank(1, 0.8, 0.5, {-0.7, 0.2}, 2, 0.4));
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  const auto random_state = [&] {
    Eigen::VectorXd w(l.A.size()), out;
    for (Eigen::Index i = 0; i < w.size(); ++i) w(i) = g(rng);
    l.A.apply(w, out);
    return out;
  };
  const Eigen::VectorXd x = random_state(), y = random_state();
  Eigen::VectorXd Ax, Ay;
  l.A.apply(x, Ax);
  l.A.apply(y, Ay);
  const double lhs = l.A.inner(x, Ay), rhs = l.A.inner(Ax, y);
  const double scale = std::sqrt(l.A.inner(Ax, Ax) * l.A.inner(y, y));
  const auto eta = l.A.displacement(Ax);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(eta[0].size());
  const double mean = std::abs(ones.dot(l.A.surface().mass() * eta[0])) / std::sqrt(eta[0].dot(l.A.surface().mass() * eta[0]));
  std::printf("<x, Ay> = %.15g, <Ax, y> = %.15g (%.1e of |Ax||y|); surface mean of Ax's eta %.1e\n", lhs, rhs,
              std::abs(lhs - rhs) / scale, mean);
  EXPECT_LT(std::abs(lhs - rhs), 1e-10 * scale);
  EXPECT_LT(mean, 1e-10);
}

// On the axis the sphere's liquid may turn rigidly about a tilted axis, its surface the cylinder about that axis: λ = 1
// exactly, the only coupled mode, E = A_f + K2 in closed form (tests/modes/test_free_surface_mesh.cpp derives it).
// Measured 2026-12-02 (P4, h 0.35, 5 900 dofs): λ 3.2e-6 from 1, E 5.6e-4 below (the rest of the weight spread over
// discrete modes next to it, each below the floor: P3 h 0.35, 0.25 gave 1.1e-2, 3.0e-3), the Gram matrix's xx entry
// A_f + K2 to 4e-7 (J_D = 0 for a sphere).
TEST(OffAxisFill, SphereOnTheAxisTurnsRigidly) {
  const double fill = 0.6;
  Liquid l(tank(1, 1, fill, {0, 0}, 4, 0.35));
  FreeSurfaceSurveySettings s;
  s.max_shifts = 2;  // the heaviest plain nodes (the suite's time: each shift ~8 s here)
  const FreeSurfaceSurvey v = survey_free_surface_modes(l.A, s);
  const double b = l.A.surface().radius(), u = std::sqrt(1 - b * b), pi = std::numbers::pi;
  const double A_f = pi * (0.5 * (u - 2 * u * u * u / 3 + u * u * u * u * u / 5) - 0.5 * b * b * b * b * u +
                           2 * ((1 - b * b) * u * u * u / 3 - u * u * u * u * u / 5));
  const double K2 = 2 * pi * b * b * u * u * u / 3;
  ASSERT_FALSE(v.modes.empty());
  const FreeSurfaceMode& top = v.modes.front();
  const double next = v.modes.size() > 1 ? v.modes[1].transverse() : 0.0;
  std::printf("sphere fill %.1f, %d dofs, %zu rows, %d shifts: lambda %.10f (1: %.1e, bound %.1e), E %.10f, A_f + K2 "
              "%.10f (%.1e), next E %.1e; gram_xx %.10f (%.1e)\n", fill, l.space.ndof(), v.modes.size(), v.shifts,
              top.lambda, std::abs(top.lambda - 1), top.residual, top.transverse(), A_f + K2,
              relative(top.transverse(), A_f + K2), next, v.gram(0, 0).real(), relative(v.gram(0, 0).real(), A_f + K2));
  EXPECT_NEAR(top.lambda, 1.0, 1e-5);
  EXPECT_LT(relative(top.transverse(), A_f + K2), 2e-3);
  EXPECT_LT(next, 1e-6 * top.transverse());
  EXPECT_LT(relative(v.gram(0, 0).real(), A_f + K2), 1e-5);
  EXPECT_LT((v.total - v.gram).norm(), 1e-10 * v.gram.norm());  // the Gauss rule's weights sum to the Gram matrix
}

// A spheroid (c/a = 0.8) filled to 0.7 on the axis: its modes with transverse weight against the meridian solver, an
// independent discretisation (P6 triangles, dense and complete). Measured 2026-12-02 (P4, h 0.35): the heavy mode's λ
// to 3.1e-7 and E to 1.9e-3, the Gram matrix's xx entry the meridian sum rule A_f + K2 − J_D to 2.0e-6.
TEST(OffAxisFill, SpheroidOnTheAxisIsTheMeridianFill) {
  const double fill = 0.7, c = 0.8;
  Liquid l(tank(1, c, fill, {0, 0}, 4, 0.35));
  FreeSurfaceSurveySettings s;
  s.max_shifts = 2;
  const FreeSurfaceSurvey v = survey_free_surface_modes(l.A, s);
  geometry::MeshOptions o;
  o.order = 6;
  o.size = 0.2;
  const geometry::ShapeSpec spheroid{"spheroid", {{"a", 1.0}, {"c", c}}, {}};
  const PartialFillSpectrum ref =
      solve_partially_filled_mesh(FESpace(geometry::mesh_meridian(geometry::partially_filled(spheroid, fill), o)), 4000);
  std::printf("spheroid fill %.1f: b %.10f (meridian %.10f); gram_xx %.10f, meridian sum rule %.10f (%.1e)\n", fill,
              l.A.surface().radius(), ref.surface_radius, v.gram(0, 0).real(), ref.sum_rule,
              relative(v.gram(0, 0).real(), ref.sum_rule));
  EXPECT_NEAR(l.A.surface().radius(), ref.surface_radius, 1e-9);
  EXPECT_LT(relative(v.gram(0, 0).real(), ref.sum_rule), 2e-5);
  int compared = 0;
  for (const auto& m : v.modes) {
    if (m.transverse() < 1e-2 * ref.sum_rule) continue;
    const PartialFillPair* best = nullptr;
    for (const auto& p : ref.pairs)
      if (!best || std::abs(std::abs(p.lambda) - m.lambda) < std::abs(std::abs(best->lambda) - m.lambda)) best = &p;
    std::printf("  3-D lambda %.8f E %.8f (bound %.1e) | meridian lambda %+.8f E %.8f: %.1e, %.1e\n", m.lambda,
                m.transverse(), m.residual, best->lambda, best->coupling.E, std::abs(m.lambda - std::abs(best->lambda)),
                relative(m.transverse(), best->coupling.E));
    EXPECT_LT(std::abs(m.lambda - std::abs(best->lambda)), 1e-5);
    EXPECT_LT(relative(m.transverse(), best->coupling.E), 5e-3);
    ++compared;
  }
  EXPECT_GE(compared, 1);
}
