// The viscous fluid in 3-D cavities (docs/volume.md §7): damped modes on tetrahedra against the meridian solver
// (an axisymmetric cavity meshed in 3-D), the left eigenvectors, and the triaxial ellipsoid's spin-over mode against
// its boundary-layer limit.
#include "boundary_layer.hpp"
#include "complex_lu.hpp"
#include "ellipsoid_closed_form.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_eigensolver.hpp"
#include "viscous_forms.hpp"
#include "viscous_table.hpp"
#include "viscous_volume_krylov.hpp"
#include "viscous_volume_modes.hpp"
#include "viscous_volume_response.hpp"
#include "volume_forms.hpp"
#include "volume_mesh.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <numbers>

using namespace rc;
using namespace rc::modes;
using cd = std::complex<double>;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct VolumeRun {
  DampedVolumeMode mode;
  int unknowns = 0;
  double seconds = 0;
};

// The 1 : 0.8 : 0.6 ellipsoid tilted 0.3 rad (every entry of H couples) on a P3 mesh (h 0.3, wall 0.1): its viscous
// forms at `ek`, about the origin (the ellipsoid's centre).
ViscousVolumeForms tilted_ellipsoid_forms(double ek, int& unknowns) {
  geometry::MeshOptions mesh;
  mesh.order = 3;
  mesh.size = 0.3;
  mesh.wall_size = 0.1;
  mesh.wall_growth = 1.0;
  const VolumeTaylorHoodSpace space(
      geometry::mesh_volume({"ellipsoid", {{"a", 1.0}, {"b", 0.8}, {"c", 0.6}}, {}, 0.3}, mesh));
  unknowns = space.size();
  return assemble_viscous_volume_forms(space, {0, 0, 0}, ek, PETSC_COMM_WORLD);
}

// The damped mode nearest `target` of the ellipsoid a, b, c at `ekman` on P`order` tetrahedra.
VolumeRun ellipsoid_mode(double a, double b, double c, double ekman, int order, double size, double wall_size,
                         cd target) {
  const auto t0 = std::chrono::steady_clock::now();
  geometry::MeshOptions mesh;
  mesh.order = order;
  mesh.size = size;
  mesh.wall_size = wall_size;
  mesh.wall_growth = 1.0;
  const VolumeTaylorHoodSpace space(geometry::mesh_volume({"ellipsoid", {{"a", a}, {"b", b}, {"c", c}}, {}, 0.0}, mesh));
  const auto forms = assemble_viscous_volume_forms(space, {0, 0, 0}, ekman, PETSC_COMM_WORLD);
  const auto modes = damped_volume_modes(forms, target, 1);
  VolumeRun r;
  r.mode = modes.at(0);
  r.unknowns = space.size();
  r.seconds = seconds_since(t0);
  return r;
}

}  // namespace

// An oblate spheroid meshed in 3-D against the meridian (m = 1) solver at the same Ekman number: its spin-over mode's
// λ, and the coupling tensor's transverse trace against the meridian table's complex E.
TEST(ViscousVolume, SpheroidIsTheMeridianSolversMode) {
  const double a = 1, c = 0.5, ek = 1e-2;
  const geometry::ShapeSpec spheroid{"spheroid", {{"a", a}, {"c", c}}, {}};
  geometry::MeshOptions m;
  m.order = 6;
  m.size = 0.05;
  const TaylorHoodSpace meridian(geometry::mesh_meridian(spheroid, viscous_mesh_defaults(spheroid, ek, m)));
  const ViscousForms mf = assemble_viscous_forms(meridian, 0.0, ek, PETSC_COMM_WORLD);
  ViscousSolveSettings settings;
  settings.pairs = 1;
  settings.tolerance = 1e-12;
  settings.left_vectors = true;
  const auto mm = viscous_modes_near(mf, {1.6, 0.1}, settings).at(0);
  // The meridian pencil is complex symmetric: its left eigenvector is the right one.
  PVec diff;
  petsc_check(VecDuplicate(*mm.block, diff.out()), "VecDuplicate");
  petsc_check(VecWAXPY(diff, -1.0, *mm.left, *mm.block), "VecWAXPY");
  PetscReal dn = 0, xn = 0;
  VecNorm(diff, NORM_2, &dn);
  VecNorm(*mm.block, NORM_2, &xn);
  std::printf("meridian (%d unknowns): lambda %.10f%+.10fi, E %.10f%+.10fi; left vector - right %.1e (residual %.1e)\n",
              meridian.size(), mm.lambda.real(), mm.lambda.imag(), mm.residue.real(), mm.residue.imag(), dn / xn,
              mm.left_residual);
  EXPECT_LE(dn / xn, 1e-8);

  const VolumeRun v = ellipsoid_mode(a, a, c, ek, 4, 0.3, 0.08, mm.lambda);
  const cd E = v.mode.H(0, 0) + v.mode.H(1, 1);
  std::printf("3-D P4 (%d unknowns, %.1f s): lambda %.10f%+.10fi (%.1e), H_xx + H_yy %.10f%+.10fi (%.1e), residuals "
              "%.1e, left %.1e\n", v.unknowns, v.seconds, v.mode.lambda.real(), v.mode.lambda.imag(),
              std::abs(v.mode.lambda - mm.lambda) / std::abs(mm.lambda), E.real(), E.imag(),
              std::abs(E - mm.residue) / std::abs(mm.residue), v.mode.residual, v.mode.left_residual);
  EXPECT_LE(std::abs(v.mode.lambda - mm.lambda) / std::abs(mm.lambda), 5e-6);  // measured 1.2e-6 (P3, h 0.25: 2.4e-5)
  EXPECT_LE(std::abs(E - mm.residue) / std::abs(mm.residue), 2e-4);               // measured 5.2e-5 (P3: 2.4e-4)
  EXPECT_LE(std::abs(v.mode.H(2, 2)), 1e-6 * std::abs(E));  // an axisymmetric m = 1 mode does not couple to the spin
  std::printf("H = [%.6f%+.6fi %.6f%+.6fi %.2e; %.6f%+.6fi %.6f%+.6fi %.2e; zz %.2e]\n", v.mode.H(0, 0).real(),
              v.mode.H(0, 0).imag(), v.mode.H(0, 1).real(), v.mode.H(0, 1).imag(), std::abs(v.mode.H(0, 2)),
              v.mode.H(1, 0).real(), v.mode.H(1, 0).imag(), v.mode.H(1, 1).real(), v.mode.H(1, 1).imag(),
              std::abs(v.mode.H(1, 2)), std::abs(v.mode.H(2, 2)));
}

// The boundary-layer limit on a 3-D wall (boundary_layer.hpp) from the closed-form spin-over field: on the sphere and
// the spheroid it is the meridian quadrature's of the same field (and Greenspan's 0.259 + 2.62i for the sphere); on
// the triaxial ellipsoid it converges under panel doubling.
TEST(ViscousVolume, SurfaceBoundaryLayerLimitIsTheMeridians) {
  const auto limit = [](double a, double b, double c, int panels) {
    const EllipsoidModes m = ellipsoid_modes(a, b, c, 0.0);
    const VolumeModeVelocity V = [&](const std::array<double, 3>& x) {
      const Eigen::Vector3cd v = m.field * Eigen::Vector3d(x[0], x[1], x[2]).cast<cd>();
      return std::array<cd, 3>{v(0), v(1), v(2)};
    };
    return boundary_layer_correction(m.lambda, ellipsoid_surface(a, b, c, panels), V, m.norm2);
  };
  for (const double c : {1.0, 0.5}) {
    // The meridian form of the same field: its value in the half-plane φ = 0 is the factor of e^{iφ}.
    const EllipsoidModes m = ellipsoid_modes(1, 1, c, 0.0);
    const ModeVelocity meridian_field = [&](double r, double z) {
      const Eigen::Vector3cd v = m.field * Eigen::Vector3d(r, 0, z).cast<cd>();
      return std::array<cd, 3>{v(0), v(1), v(2)};
    };
    const cd meridian = boundary_layer_correction(m.lambda, ellipse_wall(1, c, 3200), meridian_field, m.norm2);
    const cd surface = limit(1, 1, c, 400);
    const double err = std::abs(surface - meridian) / std::abs(meridian);
    std::printf("spheroid c/a = %.1f: lambda1 on the 3-D wall %.6f%+.6fi, on the meridian %.6f%+.6fi: %.1e\n", c,
                surface.real(), surface.imag(), meridian.real(), meridian.imag(), err);
    EXPECT_LE(err, 1.5e-5);  // the critical latitudes' kinks: panels^{-3/2} (2.3e-5 at 200 panels)
  }
  const cd l1 = limit(1, 0.8, 0.6, 200), l2 = limit(1, 0.8, 0.6, 400);
  std::printf("triaxial 1 : 0.8 : 0.6: lambda1 %.6f%+.6fi (200 panels), %.6f%+.6fi (400): %.1e\n", l1.real(),
              l1.imag(), l2.real(), l2.imag(), std::abs(l1 - l2) / std::abs(l2));
  EXPECT_LE(std::abs(l1 - l2) / std::abs(l2), 1e-5);
}

// The coupling tensor from the left and right eigenvectors against the forced response: the fluid's moment about
// e_j per unit forcing about e_k, R_jk(σ) = f_jᵀ (A − σ𝓜)⁻¹ f_k, has at the damped mode λ the residue −H_jk. Eight
// forced solves on a circle about λ give it by the trapezoidal rule, with no eigenvector at all.
TEST(ViscousVolume, CouplingTensorIsTheForcedResponsesResidue) {
  const double ek = 1e-2;
  int unknowns = 0;
  const auto forms = tilted_ellipsoid_forms(ek, unknowns);
  const DampedVolumeMode mode = damped_volume_modes(forms, {1.4, 0.5}, 1).at(0);
  const int points = 8;
  const double radius = 1e-3;
  Eigen::Matrix3cd residue = Eigen::Matrix3cd::Zero();
  PVec x;
  petsc_check(VecDuplicate(forms.couplings[0], x.out()), "VecDuplicate");
  for (int p = 0; p < points; ++p) {
    const cd step = radius * std::exp(cd(0, 2 * std::numbers::pi * p / points)), sigma = mode.lambda + step;
    PMat S;
    petsc_check(MatDuplicate(forms.forms.A, MAT_COPY_VALUES, S.out()), "MatDuplicate");
    petsc_check(MatAXPY(S, -sigma.real(), forms.forms.M, SUBSET_NONZERO_PATTERN), "MatAXPY");
    petsc_check(MatAXPY(S, -sigma.imag(), forms.forms.iM, SUBSET_NONZERO_PATTERN), "MatAXPY");
    ComplexLu lu(PETSC_COMM_WORLD, "test_");
    lu.factor(S);
    for (int k = 0; k < 3; ++k) {
      lu.solve(forms.couplings[k], x);
      for (int j = 0; j < 3; ++j) residue(j, k) += step * block_bilinear(forms.couplings[j], x) / double(points);
    }
  }
  const double err = (residue + mode.H).cwiseAbs().maxCoeff() / mode.H.cwiseAbs().maxCoeff();
  std::printf("tilted 1 : 0.8 : 0.6 at Ek %.0e (%d unknowns): lambda %.10f%+.10fi; H from the eigenvectors against "
              "the forced response's residue: %.1e (largest entry %.4f, H_zz %.4f)\n", ek, unknowns,
              mode.lambda.real(), mode.lambda.imag(), err, mode.H.cwiseAbs().maxCoeff(), std::abs(mode.H(2, 2)));
  EXPECT_LE(err, 1e-6);
  EXPECT_GT(std::abs(mode.H(1, 2)), 1e-3 * mode.H.cwiseAbs().maxCoeff());  // the tilt couples the axial rotation
  EXPECT_GT((mode.H - mode.H.adjoint()).cwiseAbs().maxCoeff(), 1e-4 * mode.H.cwiseAbs().maxCoeff())
      << "a damped mode's H is not Hermitian: the left vector is not x̄";
}

// The 3-D response table's reduction (viscous_volume_krylov.hpp) on the tilted ellipsoid at Ek = 1e-2: its poles' R
// (as a table's rows give it, each pole with its conjugate partner) is the forced response at frequencies the search
// never saw — in the window, beyond it, off the real axis and at σ < 0, which the table holds by symmetry only —, it
// is R to rounding at a frequency given as exact (and at its mirror −s̄), and its pole nearest the spin-over is the
// eigen-solver's damped mode, with its coupling tensor.
TEST(ViscousVolume, ResponseTableIsTheForcedResponse) {
  const auto t0 = std::chrono::steady_clock::now();
  const double ek = 1e-2;
  int unknowns = 0;
  const auto forms = tilted_ellipsoid_forms(ek, unknowns);
  std::vector<double> window, beyond;
  for (int i = 0; i <= 40; ++i) window.push_back(2.5 * i / 40);
  for (double t = 3.75; t <= 2500; t *= 1.5) beyond.push_back(t);
  VolumeKrylovOptions options;
  options.tolerance = 1e-6;
  options.exact_at = {{1.05, -0.01}};  // and by the symmetry −s̄ = −1.05 − 0.01i
  const VolumeKrylovReduction k = volume_krylov_reduction(forms, window, beyond, options);
  const std::vector<VolumePole> poles = volume_poles(k.model);
  const std::vector<cd> checks{0.37, 1.13, {1.71, 0.05}, 2.2, 3.1, -1.3, {0.8, -0.02}, 40.0, {1.05, -0.01}, {-1.05, -0.01}};
  const std::vector<Eigen::Matrix3cd> R = forced_volume_response(forms, checks);
  double err = 0, exact = 0;
  for (std::size_t i = 0; i < checks.size(); ++i) {
    const double e = ((pole_sum(poles, checks[i]) - R[i]).cwiseAbs().array() / k.scale.array()).maxCoeff();
    (i + 2 < checks.size() ? err : exact) = std::max(i + 2 < checks.size() ? err : exact, e);
  }
  const DampedVolumeMode mode = damped_volume_modes(forms, {1.4, 0.5}, 1).at(0);
  const VolumePole* nearest = &poles.front();
  double decay_min = 1e300;
  int damped_only = 0;
  for (const VolumePole& p : poles) {
    if (std::abs(p.lambda - mode.lambda) < std::abs(nearest->lambda - mode.lambda)) nearest = &p;
    decay_min = std::min(decay_min, p.lambda.imag());
    if (p.lambda.real() == 0) ++damped_only;
  }
  const double dl = std::abs(nearest->lambda - mode.lambda) / std::abs(mode.lambda);
  const double dH = (nearest->H - mode.H).cwiseAbs().maxCoeff() / mode.H.cwiseAbs().maxCoeff();
  std::printf("tilted 1 : 0.8 : 0.6 at Ek %.0e (%d unknowns): %zu expansion points, %d + %d vectors, %zu poles (%d "
              "purely damped); estimate %.1e, check %.1e; R from the poles against %zu forced solves %.1e of each "
              "entry's scale, at the --exact-at point and its mirror %.1e; spin-over pole against the eigen-solver: "
              "lambda %.1e, H %.1e; smallest decay %.2e (%.1f s)\n",
              ek, unknowns, k.points.size(), k.primal_vectors, k.dual_vectors, poles.size(), damped_only,
              k.estimate, k.check_error, checks.size() - 2, err, exact, dl, dH, decay_min, seconds_since(t0));
  EXPECT_TRUE(k.within_tolerance);
  EXPECT_LE(err, options.tolerance);  // measured 1.1e-10 (2026-11-28)
  EXPECT_LE(exact, 1e-10);            // 4.7e-13: exact to rounding where asked
  EXPECT_LE(dl, 1e-6);                // 3.7e-9: a Ritz value, as good as R needs it
  EXPECT_LE(dH, 1e-4);                // 1.2e-7
  EXPECT_GE(decay_min, 0.0) << "the Galerkin model is passive: every pole decays";
  EXPECT_GT(damped_only, 0) << "the spin-up's purely damped poles near sigma = 0";
}

// Wall layers (geometry/volume_wall_layers.hpp) on a tilted ellipsoid: the mesh is conforming and ends on the wall — every
// node of every face that one tetrahedron alone has (the no-slip wall of the Taylor–Hood space) lies on the exact
// ellipsoid, so no face between the layers and the core is taken for wall — and the first layer is as thin as asked.
TEST(ViscousVolume, WallLayersConformAndEndOnTheWall) {
  const double a = 1, b = 0.8, c = 0.6, tilt = 0.3, first = 0.01;
  geometry::MeshOptions mesh;
  mesh.order = 3;
  mesh.size = 0.3;
  mesh.wall_size = first;
  mesh.wall_layer = 0.05;
  mesh.wall_growth = 1.0;
  const auto m = geometry::mesh_volume({"ellipsoid", {{"a", a}, {"b", b}, {"c", c}}, {}, tilt}, mesh);
  const VolumeTaylorHoodSpace space(m);
  const auto on_wall = [&](const std::array<double, 3>& p) {  // back to the ellipsoid's frame: turn by −tilt about x
    const double y = std::cos(tilt) * p[1] + std::sin(tilt) * p[2], z = -std::sin(tilt) * p[1] + std::cos(tilt) * p[2];
    return p[0] * p[0] / (a * a) + y * y / (b * b) + z * z / (c * c) - 1;
  };
  // The Taylor–Hood space's wall nodes carry no velocity unknown: those are the nodes with no dof in any component.
  std::vector<char> free(m.nodes.size(), 0);
  for (std::size_t e = 0; e < space.num_elements(); ++e)
    for (int i = 0; i < space.velocity_nodes_per_element(); ++i)
      if (space.velocity(e, 0)[i] >= 0) free[m.tetrahedra[e * m.nodes_per_element + i]] = 1;
  double worst = 0, nearest_inside = 1;
  int wall = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const double g = on_wall(m.nodes[n]);
    if (!free[n]) {
      ++wall;
      worst = std::max(worst, std::abs(g));
    } else {
      nearest_inside = std::min(nearest_inside, -g);
    }
  }
  std::printf("layered ellipsoid: %zu tetrahedra, %d wall nodes of %zu, wall equation residual %.1e, the nearest "
              "inner node %.4f inside (level set)\n", m.num_tetrahedra(), wall, m.nodes.size(), worst, nearest_inside);
  EXPECT_EQ(wall, space.wall_nodes());
  EXPECT_LE(worst, 1e-12);
  // The first layer's nodes (order 3: a third of it) sit about first/3 from the wall: the level set there is ~2 d/c.
  EXPECT_LT(nearest_inside, 2 * first / c);
  EXPECT_GT(nearest_inside, 0.1 * first / a);
  // --near-wall-size: the core graded towards its wall, so the layers' triangles along the wall are finer — more wall
  // nodes, every one still on the exact ellipsoid.
  mesh.near_wall_size = 0.12;
  const auto fine = geometry::mesh_volume({"ellipsoid", {{"a", a}, {"b", b}, {"c", c}}, {}, tilt}, mesh);
  const VolumeTaylorHoodSpace fine_space(fine);
  std::vector<char> fine_free(fine.nodes.size(), 0);
  for (std::size_t e = 0; e < fine_space.num_elements(); ++e)
    for (int i = 0; i < fine_space.velocity_nodes_per_element(); ++i)
      if (fine_space.velocity(e, 0)[i] >= 0) fine_free[fine.tetrahedra[e * fine.nodes_per_element + i]] = 1;
  double fine_worst = 0;
  for (std::size_t n = 0; n < fine.nodes.size(); ++n)
    if (!fine_free[n]) fine_worst = std::max(fine_worst, std::abs(on_wall(fine.nodes[n])));
  std::printf("with --near-wall-size 0.12: %d wall nodes (%d without), wall equation residual %.1e\n",
              fine_space.wall_nodes(), wall, fine_worst);
  EXPECT_GT(fine_space.wall_nodes(), 2 * wall);
  EXPECT_LE(fine_worst, 1e-12);
}

namespace {

// The measure of a mesh: Σ det J over a Gauss rule exact for its isoparametric map's Jacobian.
double mesh_volume_sum(const geometry::VolumeMesh& m) {
  const auto ref = geometry::reference_tetrahedron(m.order, 3 * (m.order - 1));
  const int npe = m.nodes_per_element;
  double sum = 0;
  for (std::size_t t = 0; t < m.num_tetrahedra(); ++t)
    for (std::size_t q = 0; q < ref.weights.size(); ++q) {
      double j[3][3] = {};
      for (int a = 0; a < npe; ++a)
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d) j[c][d] += m.nodes[m.tetrahedra[t * npe + a]][c] * ref.dN[(q * npe + a) * 3 + d];
      sum += ref.weights[q] * (j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                               j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                               j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]));
    }
  return sum;
}

// The largest |g| over the nodes of the Taylor–Hood space's wall (those with no velocity unknown) and their number.
template <class Level>
std::pair<double, int> wall_residual(const geometry::VolumeMesh& m, const Level& g) {
  const VolumeTaylorHoodSpace space(m);
  std::vector<char> free(m.nodes.size(), 0);
  for (std::size_t e = 0; e < space.num_elements(); ++e)
    for (int i = 0; i < space.velocity_nodes_per_element(); ++i)
      if (space.velocity(e, 0)[i] >= 0) free[m.tetrahedra[e * m.nodes_per_element + i]] = 1;
  double worst = 0;
  int wall = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (!free[n]) {
      ++wall;
      worst = std::max(worst, std::abs(g(m.nodes[n])));
    }
  EXPECT_EQ(wall, space.wall_nodes());
  return {worst, wall};
}

}  // namespace

// Wall layers on a user's file (docs/volume.md §7, "Wall layers"): the file meshed at the wall's size, its wall
// offset inwards, gmsh's core inside, prisms out to the first mesh's curved wall. On a spheroid file every wall node
// lies on the spheroid, the layered mesh fills the cavity (its wall is the file's own mesh's without layers, node for
// node, so its measure must be that mesh's to rounding: no gap, no overlap) and the first layer is as thin as asked. On the cylinder
// file, whose wall has two circular edges (offset along their bisectors), the same. Layers thicker than the wall's
// radius of curvature are refused in one line.
TEST(ViscousVolume, WallLayersOfAUserFileFillItAndEndOnItsWall) {
  geometry::MeshOptions mesh;
  mesh.order = 3;
  mesh.size = 0.3;
  mesh.wall_size = 0.01;
  mesh.wall_layer = 0.05;
  mesh.wall_growth = 1.0;
  struct Case {
    const char* file;
    double volume;
    std::function<double(const std::array<double, 3>&)> level;  // 0 on the wall, < 0 inside
  };
  const Case cases[] = {
      {"spheroid.geo", 4 * std::numbers::pi / 3 * 0.5,
       [](const std::array<double, 3>& p) { return p[0] * p[0] + p[1] * p[1] + 4 * p[2] * p[2] - 1; }},
      {"cylinder.geo", 2 * std::numbers::pi,
       [](const std::array<double, 3>& p) {
         return std::max(std::sqrt(p[0] * p[0] + p[1] * p[1]) - 1, std::abs(p[2]) - 1);
       }}};
  for (const Case& c : cases) {
    const geometry::VolumeShapeSpec shape{"volume", {}, std::string(RC_VOLUMES_DIR) + "/" + c.file, 0.0};
    const auto layered = geometry::mesh_volume(shape, mesh);
    geometry::MeshOptions plain = mesh;
    plain.wall_size = 0;
    plain.wall_layer = 0;
    const auto unlayered = geometry::mesh_volume(shape, plain);
    const auto [worst, wall] = wall_residual(layered, c.level);
    double nearest_inside = 1;
    for (const auto& p : layered.nodes)
      if (c.level(p) < -1e-9) nearest_inside = std::min(nearest_inside, -c.level(p));
    const double measure = mesh_volume_sum(layered), plain_measure = mesh_volume_sum(unlayered);
    const double gap = std::abs(measure / plain_measure - 1);
    std::printf("%s with layers: %zu tetrahedra, %d wall nodes, wall residual %.1e, measure against the mesh without "
                "layers %.1e (both against the exact volume %.1e), the nearest inner node %.4f inside (level set)\n",
                c.file, layered.num_tetrahedra(), wall, worst, gap, std::abs(measure / c.volume - 1), nearest_inside);
    EXPECT_LE(worst, 1e-12);
    EXPECT_LE(gap, 1e-12);
    EXPECT_LT(nearest_inside, 2 * mesh.wall_size);
    EXPECT_GT(nearest_inside, 0.05 * mesh.wall_size);
  }
  geometry::MeshOptions thick = mesh;
  thick.wall_size = 0.1;
  thick.wall_layer = 0.3;  // the spheroid's rim bends with radius c²/a = 0.25
  try {
    geometry::mesh_volume({"volume", {}, std::string(RC_VOLUMES_DIR) + "/spheroid.geo", 0.0}, thick);
    ADD_FAILURE() << "layers thicker than the rim's radius of curvature were taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("fold"), std::string::npos) << e.what();
  }
}

// The early memory refusal's arithmetic (geometry/linear_tet_counts.hpp): the linear mesh's counts, taken before gmsh
// places the high-order nodes, give exactly the unknowns the two spaces then number on their own — VolumeSpace's every
// node but one, VolumeTaylorHoodSpace's velocity off the wall and pressure of one order less — at orders 2 to 4, on a
// tilted ellipsoid (curved wall) and on a user's box (flat faces, sharp edges).
TEST(VolumeMemory, LinearCountsPredictTheSpacesUnknowns) {
  const geometry::VolumeShapeSpec shapes[] = {{"ellipsoid", {{"a", 1.0}, {"b", 0.8}, {"c", 0.6}}, {}, 0.3},
                                              {"volume", {}, std::string(RC_VOLUMES_DIR) + "/box.geo", 0.0}};
  for (const auto& shape : shapes)
    for (int order = 2; order <= 4; ++order) {
      geometry::MeshOptions mesh;
      mesh.order = order;
      mesh.size = 0.3;
      geometry::LinearTetCounts counts;
      const auto m = geometry::mesh_volume(shape, mesh, [&](const geometry::LinearTetCounts& c) { counts = c; });
      ASSERT_GT(counts.tetrahedra, 0u);
      EXPECT_EQ(counts.tetrahedra, m.num_tetrahedra());
      EXPECT_EQ(counts.vertices - counts.edges + counts.faces - counts.tetrahedra, 1u);  // Euler: a ball
      const VolumeSpace scalar(m);
      EXPECT_EQ(counts.nodes(order) - 1, static_cast<std::size_t>(scalar.ndof())) << shape.kind << " P" << order;
      const VolumeTaylorHoodSpace th(m);
      EXPECT_EQ(3 * (counts.nodes(order) - counts.wall_nodes(order)) + counts.nodes(order - 1) - 1,
                static_cast<std::size_t>(th.size()))
          << shape.kind << " P" << order;
      EXPECT_EQ(counts.wall_nodes(order), static_cast<std::size_t>(th.wall_nodes())) << shape.kind << " P" << order;
    }
}
