// A partially filled tank by the mesh method (modes/freesurface/free_surface_mesh.hpp): the partially filled cylinder
// on a triangle mesh against Stewartson's closed form (partial_fill_closed_form.hpp) and the separated solver's
// couplings (partial_fill_cylinder.hpp), and the sum rule Σ E = A_f(O) + K(O) − J_D(O) for shapes without a closed
// form (sphere, cone). Every comparison prints its error.
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "free_surface_mesh.hpp"
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
