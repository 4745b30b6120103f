// The viscous partially filled tank (modes/viscous/viscous_forms.hpp with a free surface): the Taylor–Hood pencil with
// the surface displacement as unknowns and the stress-free surface, against the ideal free-surface closed form
// (Stewartson's partially filled cylinder) at Ek = 0, and its approach to the boundary-layer limit with the walls'
// Ekman layers only. Every comparison prints its error.
#include "complex_lu.hpp"
#include "fe_space.hpp"
#include "free_surface.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_eigensolver.hpp"
#include "viscous_forms.hpp"
#include "viscous_response.hpp"
#include "partial_fill_closed_form.hpp"
#include "partial_fill_cylinder.hpp"
#include "separable_cylinder.hpp"
#include "poincare_forms.hpp"
#include "boundary_layer.hpp"
#include "viscous_table.hpp"
#include "meridian_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

using namespace rc;
using namespace rc::modes;
using cd = std::complex<double>;

namespace {

constexpr double kPi = std::numbers::pi;
const cd I(0, 1);

// The damped mode nearest `target` of the cylinder (radius 1, height 2) filled to 0.9 at Ekman number ek, on the
// viscous solver's default mesh for that Ek (wall layers along the no-slip walls, none along the free surface).
// The interior elements are half the default's: the contact lines, where the no-slip lids meet the stress-free surface,
// make λ converge slowly with the element size, even with the mesh refined towards them (docs/viscous.md, "Partially
// filled tanks").
ViscousForms partially_filled_forms(double ek, double size) {
  const geometry::ShapeSpec cylinder{"cylinder", {{"radius", 1.0}, {"height", 2.0}}, {}};
  const geometry::ShapeSpec liquid = geometry::partially_filled(cylinder, 0.9);
  geometry::MeshOptions o;
  o.order = 6;
  o.size = size;
  const TaylorHoodSpace space(geometry::mesh_meridian(liquid, viscous_mesh_defaults(liquid, ek, o)));
  const double zc = integrate_fluid(space.geometry()).centroid_z;
  return assemble_viscous_forms(space, zc, ek, PETSC_COMM_SELF);
}

ViscousMode partially_filled_mode(double ek, cd target, double size = 0.0625) {
  const ViscousForms forms = partially_filled_forms(ek, size);
  ViscousSolveSettings settings;
  settings.pairs = 1;
  return viscous_modes_near(forms, target, settings).front();
}

// Stewartson's heaviest mode of the fill 0.9 cylinder (2h/a = 2) in closed form: p = F(ξr) sin(kz), F = J1 + cY1,
// k = π/2, ξ = k √(κ² − 1), c from the wall's r p_r + κ p = 0; V from p (e^{iλt}, m = 1, ω0 = 1):
//   V_r = −i(λ p_r + 2p/r)/D,   V_φ = (λ p/r + 2 p_r)/D,   V_z = i p_z/λ,   D = 4 − λ²,
// and the surface displacement η = V_r(b, z)/(iλ).
struct PartialFillMode {
  double lambda = 0, kappa = 0, xi = 0, k = kPi / 2, c = 0, b = 0;
  double F(double x) const { return std::cyl_bessel_j(1, x) + c * std::cyl_neumann(1, x); }
  double dF(double x) const {  // F′(x)
    return std::cyl_bessel_j(0, x) - std::cyl_bessel_j(1, x) / x + c * (std::cyl_neumann(0, x) - std::cyl_neumann(1, x) / x);
  }
  std::array<cd, 3> operator()(double r, double z) const {
    const double D = 4 - lambda * lambda, p = F(xi * r) * std::sin(k * z), pr = xi * dF(xi * r) * std::sin(k * z),
                 pz = F(xi * r) * k * std::cos(k * z);
    return {-I * (lambda * pr + 2 * p / r) / D, cd((lambda * p / r + 2 * pr) / D), I * pz / lambda};
  }
};

PartialFillMode heaviest_mode() {
  PartialFillMode m;
  m.b = exact::partial_fill_surface_radius(1.0, 0.9);
  for (const auto& e : exact::partially_filled_cylinder_modes(1.0, 2.0, 0.9))
    if (e.axial == 0 && std::abs(e.lambda - 0.9829) < 1e-3) m.lambda = e.lambda;
  m.kappa = 2 / m.lambda;
  m.xi = m.k * std::sqrt(m.kappa * m.kappa - 1);
  const auto g = [&](double x, double f, double df) { return x * df + m.kappa * f; };  // at r = a = 1
  const double x = m.xi;
  const double gJ = g(x, std::cyl_bessel_j(1, x), std::cyl_bessel_j(0, x) - std::cyl_bessel_j(1, x) / x);
  const double gY = g(x, std::cyl_neumann(1, x), std::cyl_neumann(0, x) - std::cyl_neumann(1, x) / x);
  m.c = -gJ / gY;
  return m;
}

// Composite Gauss–Legendre points and weights on [lo, hi].
std::vector<std::pair<double, double>> gauss(double lo, double hi, int panels) {
  const geometry::ReferenceEdge e = geometry::reference_edge(1, 15);
  std::vector<std::pair<double, double>> out;
  for (int p = 0; p < panels; ++p)
    for (std::size_t q = 0; q < e.points.size(); ++q)
      out.push_back({lo + (hi - lo) * (p + e.points[q]) / panels, (hi - lo) * e.weights[q] / panels});
  return out;
}

// The no-slip walls of the liquid annulus, fluid on the left: the bottom (r from b to 1), the side, the top.
std::vector<WallPoint> annulus_walls(double b, int panels) {
  std::vector<WallPoint> w;
  for (const auto& [r, wt] : gauss(b, 1.0, panels)) w.push_back({r, -1.0, 1.0, 0.0, wt});
  for (const auto& [z, wt] : gauss(-1.0, 1.0, panels)) w.push_back({1.0, z, 0.0, 1.0, wt});
  for (const auto& [r, wt] : gauss(b, 1.0, panels)) w.push_back({r, 1.0, -1.0, 0.0, wt});
  return w;
}

}  // namespace

// The closed-form mode's coupling, with the energy and the coupling of its surface (docs/physics.md §2, "Partially
// filled tanks"), gives back the separated solver's E = 2.08338940: the fields and the norm the boundary-layer limit
// uses below are right.
TEST(ViscousFreeSurface, ClosedFormModeHasStewartsonsCoupling) {
  const PartialFillMode m = heaviest_mode();
  const auto R = gauss(m.b, 1.0, 16), Z = gauss(-1.0, 1.0, 16);
  double kinetic = 0, surface = 0;
  cd coupling = 0;
  for (const auto& [r, wr] : R)
    for (const auto& [z, wz] : Z) {
      const auto V = m(r, z);
      kinetic += (std::norm(V[0]) + std::norm(V[1]) + std::norm(V[2])) * r * wr * wz;
      coupling += I * kPi * (-z * (V[0] - I * V[1]) + r * V[2]) * r * wr * wz;
    }
  for (const auto& [z, wz] : Z) {
    const cd eta = m(m.b, z)[0] / (I * m.lambda);
    surface += std::norm(eta) * wz;
    coupling += kPi * m.b * m.b * z * eta * wz;
  }
  const double norm2 = 2 * kPi * (kinetic + m.b * m.b * surface), E = 2 * std::norm(coupling) / norm2;
  const double D = 4 - m.lambda * m.lambda;
  const double surface_condition = m.b * m.xi * m.dF(m.xi * m.b) + (m.kappa - D) * m.F(m.xi * m.b);
  std::printf("closed form: lambda %.12f, xi %.10f, c %.10f; free surface b p_r + (kappa - D) p = %.1e; E %.10f "
              "(separated 2.0833893977, %.1e)\n", m.lambda, m.xi, m.c, surface_condition, E,
              std::abs(E - 2.0833893977) / 2.0833893977);
  EXPECT_LT(std::abs(surface_condition), 1e-9);
  EXPECT_LT(std::abs(E - 2.0833893977) / 2.0833893977, 1e-8);
}

// The damped mode tends to the ideal one with the walls' Ekman layers only (the stress-free surface has none):
// (λ − λ0)/Ek^{1/2} = λ1 + O(Ek^{1/2}), and one Richardson step on Ek = 1e-3 and 1e-4 must land on the boundary-layer
// λ1 of the closed-form mode (boundary_layer.hpp) — as for the completely filled cylinder (test_viscous.cpp); here on
// Ek = 1e-3 and 3e-4, to 3 % (measured 2.2 %; with 1e-4, 1.5 % and 1.1 %: docs/viscous.md, "Partially filled tanks").
TEST(ViscousFreeSurface, HeaviestModeExtrapolatesToTheBoundaryLayerLimit) {
  const PartialFillMode m = heaviest_mode();
  double kinetic = 0, surface = 0;
  const auto R = gauss(m.b, 1.0, 16), Z = gauss(-1.0, 1.0, 16);
  for (const auto& [r, wr] : R)
    for (const auto& [z, wz] : Z) {
      const auto V = m(r, z);
      kinetic += (std::norm(V[0]) + std::norm(V[1]) + std::norm(V[2])) * r * wr * wz;
    }
  for (const auto& [z, wz] : Z) surface += std::norm(m(m.b, z)[0] / m.lambda) * wz;
  const double norm2 = 2 * kPi * (kinetic + m.b * m.b * surface);
  const cd limit = boundary_layer_correction(m.lambda, annulus_walls(m.b, 100), m, norm2);
  std::vector<cd> slope;
  const std::vector<double> eks = {1e-3, 3e-4};
  for (double ek : eks) {
    const ViscousMode v = partially_filled_mode(ek, {m.lambda, 2 * std::sqrt(ek)});
    slope.push_back((v.lambda - m.lambda) / std::sqrt(ek));
    std::printf("Ek %.0e: lambda %.9f decay %.9f, (lambda - lambda0)/Ek^1/2 = %.5f%+.5fi, E %.6f%+.6fi\n", ek,
                v.lambda.real(), v.lambda.imag(), slope.back().real(), slope.back().imag(), v.residue.real(),
                v.residue.imag());
  }
  const double h1 = std::sqrt(eks[0]), h2 = std::sqrt(eks[1]);
  const cd extrapolated = (slope[1] * h1 - slope[0] * h2) / (h1 - h2);
  std::printf("extrapolated lambda1 = %.5f%+.5fi, boundary-layer formula (walls only) %.5f%+.5fi, difference %.1e "
              "relative\n", extrapolated.real(), extrapolated.imag(), limit.real(), limit.imag(),
              std::abs(extrapolated - limit) / std::abs(limit));
  EXPECT_LE(std::abs(extrapolated - limit), 0.03 * std::abs(limit));
}

// The offset coupling t (a + c t about a joint c below the centroid) of the damped surface wave, the mode even about
// the mid-plane that couples through t alone (a = 0 about the centroid), against the ideal mode's from the separated
// solver: they differ by O(Ek^{1/2}) (measured 0.26 % at Ek = 1e-3).
TEST(ViscousFreeSurface, SurfaceWaveOffsetCouplingTendsToTheIdeal) {
  const double b = exact::partial_fill_surface_radius(1.0, 0.9);
  const PartialFillSpectrum ideal =
      solve_partially_filled_cylinder(1.0, 2.0, 0.9, SeparableGrid::graded(1.0, 2.0, 8, 6, 12, 2, b));
  const PartialFillPair* wave = nullptr;
  for (const auto& p : ideal.pairs)
    if (p.lambda < -2 && (!wave || std::abs(p.coupling.t) > std::abs(wave->coupling.t))) wave = &p;
  ASSERT_NE(wave, nullptr);
  const double ek = 1e-3;
  const ViscousMode v = partially_filled_mode(ek, {wave->lambda, 2 * std::sqrt(ek)}, 0.125);
  const double dt = std::abs(std::abs(v.offset) - std::abs(wave->coupling.t)) / std::abs(wave->coupling.t);
  std::printf("surface wave: ideal lambda %.9f, t %.9f (a %.1e); Ek %.0e: lambda %.9f%+.9fi, t %.9f%+.9fi (|t| %.1e "
              "relative), |a| %.1e\n", wave->lambda, wave->coupling.t, wave->coupling.a, ek, v.lambda.real(),
              v.lambda.imag(), v.offset.real(), v.offset.imag(), dt, std::sqrt(std::abs(v.residue) / 2));
  EXPECT_LT(dt, 3 * std::sqrt(ek) * 0.1);
  EXPECT_LT(std::abs(v.lambda.real() - wave->lambda), 3 * std::sqrt(ek));
}

// cavity-modes response --fill --ekman (viscous_response.hpp, OffsetResponse): the forced solves' R_ff, R_fg, R_gg about
// a damped mode λ_c, by the trapezoid rule on four points of a circle of radius 1e-4 (error of order 1e-16 relative),
// have the residues the eigensolver gives the mode: E_c, 2 a_c t_c and 2 t_c² — for the heaviest mode (odd about the
// mid-plane: t = 0) and for the surface wave (even: a = 0), the offset coupling coming only from the response.
TEST(ViscousFreeSurface, ForcedResponseResiduesAreTheModesCouplings) {
  const double ek = 1e-3;
  const ViscousForms forms = partially_filled_forms(ek, 0.125);
  ForcedResponse response(forms);
  ViscousSolveSettings settings;
  settings.pairs = 1;
  const double b = exact::partial_fill_surface_radius(1.0, 0.9);
  const PartialFillSpectrum ideal =
      solve_partially_filled_cylinder(1.0, 2.0, 0.9, SeparableGrid::graded(1.0, 2.0, 8, 6, 12, 2, b));
  const PartialFillPair* wave = nullptr;  // the surface wave of the test above
  for (const auto& p : ideal.pairs)
    if (p.lambda < -2 && (!wave || std::abs(p.coupling.t) > std::abs(wave->coupling.t))) wave = &p;
  ASSERT_NE(wave, nullptr);
  for (const cd target : {cd(0.98, 0.05), cd(wave->lambda, 2 * std::sqrt(ek))}) {
    const ViscousMode m = viscous_modes_near(forms, target, settings).front();
    const double delta = 1e-4;
    OffsetResponse res{0, 0, 0};
    for (const cd u : {cd(1, 0), cd(0, 1), cd(-1, 0), cd(0, -1)}) {
      const OffsetResponse r = response.with_offset(m.lambda + delta * u);
      res.ff += delta * u * r.ff / 4.0;
      res.fg += delta * u * r.fg / 4.0;
      res.gg += delta * u * r.gg / 4.0;
    }
    const double scale = std::abs(m.residue) + 2 * std::norm(m.offset);
    const double eff = std::abs(res.ff - m.residue) / scale, egg = std::abs(res.gg - 2.0 * m.offset * m.offset) / scale,
                 efg = std::abs(res.fg * res.fg - res.ff * res.gg) / (scale * scale);
    std::printf("lambda_c %.9f%+.9fi: residue of R_ff %.4e%+.4ei (E_c %.4e%+.4ei, %.1e), of R_gg %.6e%+.6ei "
                "(2 t_c^2 %.6e%+.6ei, %.1e), R_fg^2 - R_ff R_gg: %.1e (of the scale %.3g)\n", m.lambda.real(),
                m.lambda.imag(), res.ff.real(), res.ff.imag(), m.residue.real(), m.residue.imag(), eff, res.gg.real(),
                res.gg.imag(), (2.0 * m.offset * m.offset).real(), (2.0 * m.offset * m.offset).imag(), egg, efg, scale);
    EXPECT_LT(eff, 1e-7);
    EXPECT_LT(egg, 1e-7);
    EXPECT_LT(efg, 1e-7);
  }
}

// The meridian pencil is complex symmetric (viscous_forms.hpp), so σ𝓜 − A is factored as LDLᵀ from its lower triangle
// (MUMPS SYM = 2, what every forced solve and response table uses): on the partially filled cylinder, whose free
// surface adds the η̃ rows and the stress form, the solutions for both inputs agree with the LU's of the whole matrix.
// Were A or 𝓜 not symmetric, LDLᵀ would solve the lower triangle's symmetric completion, another matrix.
TEST(ViscousFreeSurface, SymmetricFactorsSolveAsTheLu) {
  const ViscousForms forms = partially_filled_forms(1e-3, 0.125);
  ASSERT_TRUE(forms.complex_symmetric);
  const cd sigma(0.7, 0.05);
  PMat S;
  petsc_check(MatDuplicate(forms.A, MAT_COPY_VALUES, S.out()), "MatDuplicate");
  petsc_check(MatScale(S, -1.0), "MatScale");
  petsc_check(MatAXPY(S, sigma.real(), forms.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(S, sigma.imag(), forms.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
  ComplexLu lu(PETSC_COMM_SELF, "test_lu_"), ldlt(PETSC_COMM_SELF, "test_ldlt_", true);
  lu.factor(S);
  ldlt.factor(S);
  EXPECT_LT(ldlt.infog(29), lu.infog(29)) << "LDLᵀ keeps one triangle of the factors";  // INFOG(29): the factors' entries
  PVec x, y, d;
  for (Vec input : {forms.coupling.get(), forms.offset_coupling.get()}) {
    petsc_check(VecDuplicate(input, x.out()), "VecDuplicate");
    petsc_check(VecDuplicate(input, y.out()), "VecDuplicate");
    petsc_check(VecDuplicate(input, d.out()), "VecDuplicate");
    lu.solve(input, x);
    ldlt.solve(input, y);
    petsc_check(VecWAXPY(d, -1.0, x, y), "VecWAXPY");
    PetscReal nd = 0, nx = 0;
    petsc_check(VecNorm(d, NORM_INFINITY, &nd), "VecNorm");
    petsc_check(VecNorm(x, NORM_INFINITY, &nx), "VecNorm");
    std::printf("%d complex unknowns, sigma %.2f%+.2fi: LDLT against LU %.1e of max|x|\n", forms.complex_size,
                sigma.real(), sigma.imag(), nd / nx);
    EXPECT_LT(nd / nx, 1e-9);
  }
}

namespace {

// The spacecraft tank of data/scenes/spacecraft_nutation.toml: a unit sphere filled to 60 % at Ek = 9.05e-7.
geometry::ShapeSpec sixty_percent_sphere() {
  return geometry::partially_filled({"sphere", {{"radius", 1.0}}, {}}, 0.6);
}
constexpr double kSpacecraftEkman = 9.05192e-7;

// The linear triangles' quality 4√3 area / Σ edge² (1: equilateral) at the free surface: every triangle with a vertex
// on r = b. Its smallest value.
double free_surface_quality(const geometry::MeridianMesh& mesh) {
  double worst = 1.0;
  for (std::size_t e = 0; e < mesh.num_triangles(); ++e) {
    const int* t = &mesh.triangles[e * mesh.nodes_per_element];
    const auto &A = mesh.nodes[t[0]], &B = mesh.nodes[t[1]], &C = mesh.nodes[t[2]];
    const bool on_surface = std::abs(A[0] - mesh.free_radius) < 1e-9 || std::abs(B[0] - mesh.free_radius) < 1e-9 ||
                            std::abs(C[0] - mesh.free_radius) < 1e-9;
    if (!on_surface) continue;
    const auto sq = [](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
    };
    const double area = 0.5 * std::abs((B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]));
    worst = std::min(worst, 4 * std::sqrt(3.0) * area / (sq(A, B) + sq(B, C) + sq(C, A)));
  }
  return worst;
}

}  // namespace

// The wall layers end at the contact lines (docs/viscous.md, "Contact lines and the wall layers"): left to continue,
// gmsh laid slivers along the free surface (quality 0.0055, 0.056 and 0.134 at these sizes, before; 0.205, 0.303 and
// 0.483 since) and the forced flow there went wrong by a factor 45 (the next test).
TEST(ViscousFreeSurface, WallLayersEndAtTheContactLines) {
  const geometry::ShapeSpec liquid = sixty_percent_sphere();
  for (const double size : {0.058, 0.04, 0.025}) {
    geometry::MeshOptions o;
    o.order = 2;  // the vertices are the order's own: the cheapest mesh with them
    o.size = size;
    const geometry::MeridianMesh mesh = geometry::mesh_meridian(liquid, viscous_mesh_defaults(liquid, kSpacecraftEkman, o));
    const double q = free_surface_quality(mesh);
    std::printf("interior size %.3f: smallest quality of a triangle at the free surface %.3f\n", size, q);
    EXPECT_GT(q, 0.15) << "size " << size;
  }
}

// The default response mesh of the spacecraft's tank at the nutation's frequency against a finer one (P4, h 0.0145,
// four times the unknowns): R within 2e-4 of it, Im R (the dissipation, what the nutation's decay comes from) within
// 1 %, and R_fg, which vanishes for the liquid (symmetric about its mid-plane), at rounding on both. Before the layers
// ended at the contact lines, the default mesh's Im R was 45 times the finer one's and R_fg 0.4 % of the scale.
TEST(ViscousFreeSurface, LowEkmanResponseOnTheDefaultMesh) {
  const geometry::ShapeSpec liquid = sixty_percent_sphere();
  const cd s(-0.2437, 0.0);
  const auto response = [&](int order, double size) {
    geometry::MeshOptions o;
    o.order = order;  // 0: the program's default (P6)
    o.size = size;    // 0: the program's default
    const ViscousForms forms =
        assemble_cavity_forms(liquid, viscous_mesh_defaults(liquid, kSpacecraftEkman, o), kSpacecraftEkman, PETSC_COMM_SELF);
    ForcedResponse r(forms);
    return r.with_offset(s);
  };
  const OffsetResponse coarse = response(0, 0.0), fine = response(4, 0.0145);
  const auto symmetry = [](const OffsetResponse& r) { return std::abs(r.fg) / std::sqrt(std::abs(r.ff * r.gg)); };
  std::printf("R at s = %.4f: default mesh %.8f%+.8fi, P4 h 0.0145 %.8f%+.8fi; R_fg / sqrt(R_ff R_gg) %.1e, %.1e\n",
              s.real(), coarse.ff.real(), coarse.ff.imag(), fine.ff.real(), fine.ff.imag(), symmetry(coarse),
              symmetry(fine));
  EXPECT_LT(std::abs(coarse.ff - fine.ff), 2e-4 * std::abs(fine.ff));
  EXPECT_NEAR(coarse.ff.imag(), fine.ff.imag(), 1e-2 * fine.ff.imag());
  EXPECT_LT(symmetry(coarse), 1e-6);
  EXPECT_LT(symmetry(fine), 1e-6);
}
