// The viscous liquid of a partially filled 3-D tank (docs/volume.md §8, "The viscous liquid's pencil";
// modes/volume/viscous_fill_surface.hpp): its forced response on tetrahedra against the meridian solver's viscous
// partial fill (an independent discretisation: P6 triangles, the m = 1 reduction) with the tank on the spin axis.
#include "fe_space.hpp"
#include "meridian_mesh.hpp"
#include "viscous_forms.hpp"
#include "viscous_response.hpp"
#include "viscous_table.hpp"
#include "viscous_volume_forms.hpp"
#include "viscous_volume_krylov.hpp"
#include "viscous_volume_response.hpp"
#include "volume_forms.hpp"
#include "volume_mesh.hpp"
#include "volume_taylor_hood.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <algorithm>

using namespace rc;
using namespace rc::modes;

namespace {

using cd = std::complex<double>;

// The m = 1 part of a transverse 2 × 2 block (viscous_volume_response.hpp): ½ (X_xx + i X_xy − i X_yx + X_yy).
cd m1_part(const FillResponse& R, int row, int col) {
  const cd I(0, 1);
  return 0.5 * (R(row, col) + I * R(row, col + 1) - I * R(row + 1, col) + R(row + 1, col + 1));
}

// The sphere filled to `fill` on the spin axis, meshed in 3-D (P`order`, h `size`), its 5 × 5 response at each σ.
// The sphere filled to `fill`, its centre `axis_distance` from the spin axis (along x), meshed in 3-D: its forms.
ViscousVolumeForms sphere_fill_forms(double fill, double ek, int order, double size, double axis_distance) {
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  const VolumeTaylorHoodSpace space(
      geometry::mesh_volume({"ellipsoid", {{"a", 1.0}, {"b", 1.0}, {"c", 1.0}}, {}, 0.0, fill, {-axis_distance, 0.0}}, o));
  return assemble_viscous_volume_forms(space, integrate_volume(space.geometry()).centroid, ek, PETSC_COMM_WORLD);
}

std::vector<FillResponse> sphere_fill_response_3d(double fill, double ek, int order, double size,
                                                  const std::vector<cd>& sigmas, double axis_distance = 0) {
  const auto t0 = std::chrono::steady_clock::now();
  geometry::MeshOptions o;
  o.order = order;
  o.size = size;
  const VolumeTaylorHoodSpace space(
      geometry::mesh_volume({"ellipsoid", {{"a", 1.0}, {"b", 1.0}, {"c", 1.0}}, {}, 0.0, fill, {-axis_distance, 0.0}}, o));
  const ViscousVolumeForms forms =
      assemble_viscous_volume_forms(space, integrate_volume(space.geometry()).centroid, ek, PETSC_COMM_WORLD);
  std::vector<FillResponse> R = forced_fill_response(forms, sigmas);
  std::printf("3-D P%d h %.2f: %d unknowns (%d velocity, %d on the surface), %.1f s\n", order, size, space.size(),
              space.velocity_dofs(), forms.forms.complex_size - space.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return R;
}

}  // namespace

// A sphere filled to 0.6 on the spin axis at Ek = 1e-2: the 3-D response's m = 1 parts — rotation-rotation, rotation
// and offset, offset-offset — converge to the meridian solver's R_ff, R_fg and R_gg (viscous_response.hpp,
// OffsetResponse; P6, h 0.05) at frequencies on both sides of the inertial band and inside it. The liquid is symmetric
// about the equator, so R_fg vanishes; the pencil is not symmetric in 3-D, yet the rotation-offset block equals the
// offset-rotation one (the reciprocity of an axisymmetric liquid). Measured 2026-12-07 (the largest error over σ,
// relative to |R_ff| + |R_gg|): P3 h 0.3 (8 921 unknowns, 3 s) 1.4e-2, P4 h 0.3 (22 442, 12 s) 6.5e-3; at σ = 0.4 +
// 0.01i R_ff is off by 4.4 % (P3 h 0.3), 2.8 % (P3 h 0.2), 2.3 % (P4 h 0.3), 1.4 % (P4 h 0.2, 65 718 unknowns, 98 s):
// the contact lines, where no-slip meets the stress-free surface, make it converge slowly (as the meridian solver's
// own: its h 0.1 and 0.05 differ by 2e-3 there).
TEST(ViscousFill3d, SphereOnTheAxisIsTheMeridianFill) {
  const double ek = 1e-2, fill = 0.6;
  const std::vector<cd> sigmas = {{-2.6, 0.02}, {-0.7, 0.05}, {0.4, 0.01}, {1.3, 0.05}, {3.1, 0.0}};
  const std::vector<FillResponse> coarse = sphere_fill_response_3d(fill, ek, 3, 0.3, sigmas);
  const std::vector<FillResponse> fine = sphere_fill_response_3d(fill, ek, 4, 0.3, sigmas);

  const geometry::ShapeSpec sphere{"sphere", {{"radius", 1.0}}, {}};
  const geometry::ShapeSpec liquid = geometry::partially_filled(sphere, fill);
  geometry::MeshOptions mo;
  mo.order = 6;
  mo.size = 0.05;
  const TaylorHoodSpace meridian(geometry::mesh_meridian(liquid, viscous_mesh_defaults(liquid, ek, mo)));
  const ViscousForms mf =
      assemble_viscous_forms(meridian, integrate_fluid(meridian.geometry()).centroid_z, ek, PETSC_COMM_WORLD);
  ForcedResponse reference(mf);
  double worst_coarse = 0, worst_fine = 0;
  for (std::size_t i = 0; i < sigmas.size(); ++i) {
    const OffsetResponse m = reference.with_offset(sigmas[i]);
    const double scale = std::abs(m.ff) + std::abs(m.gg);
    const auto error = [&](const FillResponse& R) {
      return std::max({std::abs(m1_part(R, 0, 0) - m.ff), std::abs(m1_part(R, 0, 3) - m.fg),
                       std::abs(m1_part(R, 3, 0) - m.fg), std::abs(m1_part(R, 3, 3) - m.gg)}) / scale;
    };
    const FillResponse& R = fine[i];
    const cd ff = m1_part(R, 0, 0), fg = m1_part(R, 0, 3), gf = m1_part(R, 3, 0), gg = m1_part(R, 3, 3);
    std::printf("s %+.2f%+.2fi: ff %.6f%+.6fi (meridian %.6f%+.6fi), gg %.6f%+.6fi (%.6f%+.6fi), fg %.1e, gf - fg "
                "%.1e (of the scale); error P3 %.1e, P4 %.1e\n", sigmas[i].real(), sigmas[i].imag(), ff.real(), ff.imag(),
                m.ff.real(), m.ff.imag(), gg.real(), gg.imag(), m.gg.real(), m.gg.imag(), std::abs(fg) / scale,
                std::abs(gf - fg) / scale, error(coarse[i]), error(fine[i]));
    EXPECT_LT(std::abs(m.fg), 1e-9 * scale);      // the meridian's liquid is symmetric about the equator
    EXPECT_LT(std::abs(gf - fg), 1e-4 * scale);   // measured 4e-6
    worst_coarse = std::max(worst_coarse, error(coarse[i]));
    worst_fine = std::max(worst_fine, error(fine[i]));
  }
  std::printf("largest error: P3 h 0.3 %.2e, P4 h 0.3 %.2e\n", worst_coarse, worst_fine);
  EXPECT_LT(worst_fine, 1.3e-2);
  EXPECT_LT(worst_fine, 0.7 * worst_coarse);  // it converges
}

// The same tank moved off the spin axis (its centre D from it, along x): the response continues the on-axis one and
// moves as D² (the mirror image D → −D is the same tank), as the ideal modes do (docs/volume.md §8, "Moving the tank
// off the axis"); the liquid stays symmetric about the tank's equator, so the rotations about x and y (odd in z)
// do not couple to the spin's rotation and the offsets (even). Measured 2026-12-07 (P3 h 0.3, σ = 0.4 + 0.01i): the
// shifts from D = 0.1 to 0.2 grow by 3.6 (U_x U_x), 3.1 (U_y U_y), 4.3 (U_z U_z), 3.6 (T_x T_x); the odd-even entries
// 2.5e-3 of the scale (the mesh is not symmetric about the equator).
TEST(ViscousFill3d, OffTheAxisTheResponseMovesAsTheDistanceSquared) {
  const double ek = 1e-2, fill = 0.6;
  const std::vector<cd> sigma = {{0.4, 0.01}};
  const FillResponse R0 = sphere_fill_response_3d(fill, ek, 3, 0.3, sigma, 0.0).front();
  const FillResponse R1 = sphere_fill_response_3d(fill, ek, 3, 0.3, sigma, 0.1).front();
  const FillResponse R2 = sphere_fill_response_3d(fill, ek, 3, 0.3, sigma, 0.2).front();
  for (int k : {0, 1, 2, 3}) {
    const double d1 = std::abs(R1(k, k) - R0(k, k)), d2 = std::abs(R2(k, k) - R0(k, k));
    std::printf("R_%d%d: D = 0 %.6f%+.6fi, shift at D = 0.1 %.3e, at 0.2 %.3e: ratio %.2f (D^2: 4)\n", k, k,
                R0(k, k).real(), R0(k, k).imag(), d1, d2, d2 / d1);
    EXPECT_GT(d2 / d1, 2.5);  // linear in D would give 2
    EXPECT_LT(d2 / d1, 5.5);
    EXPECT_LT(d1, 0.1 * std::abs(R0(k, k)));  // continuity: a small move moves it little
  }
  const double scale = R2.cwiseAbs().maxCoeff();
  double odd_even = 0;
  for (int j : {0, 1})
    for (int k : {2, 3, 4}) odd_even = std::max({odd_even, std::abs(R2(j, k)), std::abs(R2(k, j))});
  std::printf("D = 0.2: the largest entry between the odd and the even directions %.1e of the scale %.3g\n",
              odd_even / scale, scale);
  EXPECT_LT(odd_even, 1e-2 * scale);
}

// The response table's reduction (viscous_volume_krylov.hpp) over a partially filled tank's five directions, whose
// outputs are not its inputs (G = F̄): the sphere filled to 0.5, its centre 0.3 radii off the spin axis (no symmetry
// but the equator's), at Ek = 1e-2. Its poles' R is the forced response at frequencies the search never saw — in the
// window, beyond it, off the real axis and at σ < 0 (held by the symmetry R(−s̄) = −conj R(s) only) —, every pole
// decays (the Galerkin model is passive), and each pole's residue is of rank one (one damped mode). Measured 2026-12-07
// (P3 h 0.3, 9 662 unknowns, 16 s): 6 points, 141 poles, 2.6e-9 of each entry's scale; residues of rank one to 1e-16.
TEST(ViscousFill3d, ResponseTableIsTheForcedResponse) {
  const auto t0 = std::chrono::steady_clock::now();
  const ViscousVolumeForms forms = sphere_fill_forms(0.5, 1e-2, 3, 0.3, 0.3);
  std::vector<double> window, beyond;
  for (int i = 0; i <= 40; ++i) window.push_back(3.0 * i / 40);
  for (double t = 4.5; t <= 2500; t *= 1.5) beyond.push_back(t);
  VolumeKrylovOptions options;
  options.tolerance = 1e-6;
  const VolumeKrylovReduction k = volume_krylov_reduction(forms, window, beyond, options);
  const std::vector<VolumePole> poles = volume_poles(k.model);
  const std::vector<cd> checks{0.37, 1.13, {1.71, 0.05}, 2.2, 3.4, -1.3, {-0.6, 0.03}, {0.8, -0.02}, 40.0};
  const std::vector<FillResponse> R = forced_fill_response(forms, checks);
  double err = 0, decay_min = 1e300, rank = 0;
  for (std::size_t i = 0; i < checks.size(); ++i)
    err = std::max(err, ((pole_sum(poles, checks[i]) - R[i]).cwiseAbs().array() / k.scale.array()).maxCoeff());
  for (const VolumePole& p : poles) {
    decay_min = std::min(decay_min, p.lambda.imag());
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(p.H);
    rank = std::max(rank, svd.singularValues()(1) / svd.singularValues()(0));
  }
  std::printf("sphere filled to 0.5, 0.3 off the axis, Ek 1e-2 (%d unknowns): %zu expansion points, %d + %d vectors, "
              "%zu poles; estimate %.1e, check %.1e; R from the poles against %zu forced solves %.1e of each entry's "
              "scale; smallest decay %.2e; largest second singular value of a residue %.1e of its first (%.1f s)\n",
              forms.forms.complex_size, k.points.size(), k.primal_vectors, k.dual_vectors, poles.size(), k.estimate,
              k.check_error, checks.size(), err, decay_min, rank,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  EXPECT_TRUE(k.within_tolerance);
  EXPECT_LE(err, 10 * options.tolerance);
  EXPECT_GE(decay_min, 0.0) << "the Galerkin model is passive: every pole decays";
  EXPECT_LE(rank, 1e-6);
}
