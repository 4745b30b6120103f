// A user's section filled partially (cavity-modes section FILE --fill F): gmsh's OpenCASCADE kernel cuts the section
// at its free surface r = b (geometry/section_cut.hpp). Checked against closed forms: b and the liquid's volume for the
// torus and the capsule (whose arcs the cut rebuilds), and the annulus cut at b, whose liquid is the plain cylinder's
// at the fill 1 − b² and so has Stewartson's closed-form frequencies. Every comparison prints its error.
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "free_surface_mesh.hpp"
#include "partial_fill_closed_form.hpp"
#include "partial_fill_cylinder.hpp"
#include "separable_cylinder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

using namespace rc;
using namespace rc::modes;

namespace {

const double pi = std::acos(-1.0);

geometry::ShapeSpec section(const std::string& name) {
  return {"section", {}, std::string(RC_SECTIONS_DIR) + "/" + name};
}

PartialFillSpectrum mesh_spectrum(const geometry::ShapeSpec& shape, double fill, int order, double size) {
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  return solve_partially_filled_mesh(FESpace(geometry::mesh_meridian(geometry::partially_filled(shape, fill), o)),
                                     4000);
}

// The root in (lo, hi) of a decreasing f(b) − fill.
double decreasing_root(const std::function<double(double)>& f, double fill, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > fill ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

// The torus of data/sections/torus.geo (tube radius a = 0.4 about r = R = 1) keeps the part of its disc beyond the
// chord r = b: with d = b − R, the liquid's ∫∫ r dA = R (a² acos(d/a) − d√(a² − d²)) + (2/3)(a² − d²)^{3/2}, over
// R π a² when full. Its volume from the mesh of the cut must be F · 2π² R a².
TEST(SectionFill, TorusFreeSurfaceIsTheClosedForm) {
  const double R = 1, a = 0.4;
  const auto fraction = [&](double b) {
    const double d = b - R, s = a * a - d * d;
    return (R * (a * a * std::acos(d / a) - d * std::sqrt(s)) + 2.0 / 3.0 * s * std::sqrt(s)) / (R * pi * a * a);
  };
  for (const double fill : {0.2, 0.5, 0.9}) {
    const double b = geometry::free_surface_radius(section("torus.geo"), fill);
    const double exact = decreasing_root(fraction, fill, R - a, R + a);
    geometry::MeshOptions o;
    o.order = 6;
    o.size = 0.1;
    const FESpace space(geometry::mesh_meridian(geometry::partially_filled(section("torus.geo"), fill), o));
    const double volume = integrate_fluid(space).volume, whole = 2 * pi * pi * R * a * a;
    std::printf("torus, fill %.1f: b = %.15f (closed form %.15f, %.1e); liquid volume %.13g (F x 2 pi^2 R a^2: %.1e)\n",
                fill, b, exact, std::abs(b - exact), volume, relative(volume, fill * whole));
    EXPECT_NEAR(b, exact, 1e-12);
    EXPECT_LT(relative(volume, fill * whole), 1e-9);
  }
}

// The capsule of data/sections/capsule.geo (radius 1, a cylinder of length 2 between hemispheres) cut at b < 1: its
// liquid volume is 2π(1 − b²) + (4/3)π(1 − b²)^{3/2} of the whole 2π + 4π/3; the sum rule about two points.
TEST(SectionFill, CapsuleCutThroughItsArcs) {
  const auto volume = [](double b) {
    const double u = 1 - b * b;
    return 2 * pi * u + 4.0 / 3.0 * pi * u * std::sqrt(u);
  };
  const double fill = 0.6, whole = volume(0);
  const double b = geometry::free_surface_radius(section("capsule.geo"), fill);
  const double exact = decreasing_root([&](double r) { return volume(r) / whole; }, fill, 0, 1);
  const PartialFillSpectrum s = mesh_spectrum(section("capsule.geo"), fill, 6, 0.4);
  std::printf("capsule, fill %.1f: b = %.15f (closed form %.1e), %d dofs, liquid volume %.13g (%.1e); sum E %.12g, "
              "rule %.12g (%.1e)\n", fill, b, std::abs(b - exact), s.radial_dofs, s.fluid.volume,
              relative(s.fluid.volume, fill * whole), s.sum_E, s.sum_rule, relative(s.sum_E, s.sum_rule));
  EXPECT_NEAR(b, exact, 1e-12);
  EXPECT_NEAR(s.surface_radius, exact, 1e-12);
  EXPECT_LT(relative(s.fluid.volume, fill * whole), 1e-9);
  EXPECT_LT(relative(s.sum_E, s.sum_rule), 1e-9);
  for (const double c : {0.5, -2.0}) {
    double sum = 0;
    for (const auto& p : s.pairs) sum += coupling_about(p.coupling, c);
    std::printf("  about c = %+.1f: sum E %.12g, rule %.12g (%.1e)\n", c, sum, s.sum_rule_about(c),
                relative(sum, s.sum_rule_about(c)));
    EXPECT_LT(relative(sum, s.sum_rule_about(c)), 1e-9);
  }
}

// data/sections/annulus.geo (rod 0.3, wall 1, height 2) at fill 0.8: b² = 1 − 0.8(1 − 0.09), and the liquid b < r < 1
// is the plain cylinder's at fill 1 − b², whose heaviest modes' λ Stewartson's closed form gives.
TEST(SectionFill, AnnulusIsStewartsonsCylinder) {
  const double fill = 0.8;
  const PartialFillSpectrum s = mesh_spectrum(section("annulus.geo"), fill, 6, 0.25);
  const double b = s.surface_radius, plain = 1 - b * b;
  std::printf("annulus, fill %.1f: b = %.15f (closed form %.1e), %d dofs\n", fill, b,
              std::abs(b - std::sqrt(1 - fill * (1 - 0.09))), s.radial_dofs);
  EXPECT_NEAR(b, std::sqrt(1 - fill * (1 - 0.09)), 1e-13);
  const PartialFillSpectrum sep = solve_partially_filled_cylinder(
      1.0, 2.0, plain, SeparableGrid::graded(1.0, 2.0, 8, 6, 12, 2, exact::partial_fill_surface_radius(1.0, plain)));
  const auto closed = exact::partially_filled_cylinder_modes(1.0, 2.0, plain);
  for (int k = 0; k < 3; ++k) {
    const PartialFillPair& ref = sep.pairs[k];
    const PartialFillPair* got = &s.pairs.front();
    for (const auto& p : s.pairs)
      if (p.coupling.E > 0.1 * ref.coupling.E && std::abs(p.lambda - ref.lambda) < std::abs(got->lambda - ref.lambda))
        got = &p;
    double exact = 1e300;
    for (const auto& m : closed)
      if (std::abs(m.lambda - ref.lambda) < std::abs(exact - ref.lambda)) exact = m.lambda;
    std::printf("  lambda %.12f (closed form %.12f, %.1e), E %.10g (separated %.10g, %.1e)\n", got->lambda, exact,
                relative(got->lambda, exact), got->coupling.E, ref.coupling.E, relative(got->coupling.E, ref.coupling.E));
    EXPECT_LT(relative(got->lambda, exact), 1e-8);
    EXPECT_LT(relative(got->coupling.E, ref.coupling.E), 1e-5);
  }
}
