// 3-D cavities (docs/volume.md §3): the ellipsoid's uniform-vorticity modes (spin-over and geostrophic vortex) against
// their closed form, upright, tilted and read from a CAD file; the spheroid meshed in 3-D against the axisymmetric table; the tensor sum
// rule; the survey's coupling tensor against the pressure eigenproblem solved directly.
#include "cavity_table.hpp"
#include "ellipsoid_closed_form.hpp"
#include "qep_solver.hpp"
#include "volume_coupling.hpp"
#include "volume_forms.hpp"
#include "volume_survey.hpp"
#include "volume_table.hpp"
#include "volume_velocity.hpp"
#include "volume_zhukovsky.hpp"
#include "gmsh_library.hpp"

#include <Eigen/Geometry>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

using namespace rc;

namespace {

double max_abs(const Eigen::Matrix3cd& m) { return m.cwiseAbs().maxCoeff(); }

Eigen::Matrix3d tensor(const std::vector<double>& v) { return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v.data()); }

Eigen::Matrix3cd coupling_tensor(const ModeTable& t, std::size_t mode) {
  Eigen::Matrix3cd H;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      H(j, k) = {t.volume_cavity.coupling_re[9 * mode + 3 * j + k], t.volume_cavity.coupling_im[9 * mode + 3 * j + k]};
  return H;
}

modes::VolumeTableResult ellipsoid_table(double a, double b, double c, double tilt, int order, double size,
                                         double wall_size) {
  modes::VolumeTableRequest r;
  r.shape = {"ellipsoid", {{"a", a}, {"b", b}, {"c", c}}, {}, tilt};
  r.mesh.order = order;
  r.mesh.size = size;
  r.mesh.wall_size = wall_size;
  r.mesh.wall_growth = 1.0;
  return modes::make_volume_table(r);
}

// The table's spin-over mode, its geostrophic part and its tensors against the closed form; returns the errors.
// tol_geostrophic: the λ = 0 weight is the plain rule's (60 basis vectors), not refined by a shift.
void check_ellipsoid(const modes::VolumeTableResult& r, const modes::EllipsoidModes& exact, double tol_mode,
                     double tol_tensor, double tol_geostrophic) {
  const ModeTable& t = r.table;
  ASSERT_GE(t.size(), 1u);
  // The cluster: every kept mode within 1e-3 of the exact λ (a tilted mesh splits the mode among discrete copies).
  Eigen::Matrix3cd H = Eigen::Matrix3cd::Zero();
  double rest = 0;  // every other kept mode's weight
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::abs(t.lambda[i] - exact.lambda) < 1e-3 * exact.lambda) H += coupling_tensor(t, i);
    else rest += t.E[i];
  }
  const double scale = exact.H.trace().real();
  const double dl = std::abs(t.lambda[0] - exact.lambda) / exact.lambda, dH = max_abs(H - exact.H) / scale;
  const Eigen::Matrix3d P = exact.inertia - exact.zhukovsky;
  const double dP = (tensor(t.volume_cavity.sum_rule) - P).cwiseAbs().maxCoeff() / P.trace();
  const double dG = (tensor(t.volume_cavity.geostrophic_re) - exact.geostrophic).cwiseAbs().maxCoeff() / P.trace();
  std::printf("  %ld dofs, %.1f s: lambda %.15f (exact %.15f) rel %.1e; H %.1e; sum rule tensor %.1e; geostrophic "
              "%.1e; other modes %.1e; rule weights = I_f - J_zh to %.1e\n",
              t.ndof, t.wall_seconds, t.lambda[0], exact.lambda, dl, dH, dP, dG, rest / scale, r.sum_rule_mismatch);
  EXPECT_LT(dl, tol_mode);
  EXPECT_LT(dH, tol_mode);
  EXPECT_LT(dP, tol_tensor);
  EXPECT_LT(dG, tol_geostrophic);
  EXPECT_LT(rest, tol_tensor * scale);
  EXPECT_LT(r.sum_rule_mismatch, 1e-12);
  EXPECT_TRUE(r.survey.unsettled.empty());
}

}  // namespace

TEST(VolumeModes, TriaxialSpinOverIsTheClosedForm) {
  // P5 tetrahedra, 0.15 on the wall (the isoparametric wall is the only error: the mode's pressure is quadratic).
  // Measured 2026-12-02: P5 (18 210 unknowns, 24.7 s) λ 1.9e-7, H 4.2e-6, sum-rule tensor 3.0e-7, geostrophic 4.1e-7;
  // P6 (30 505, 42.3 s) 3.1e-8, 1.5e-7, 3.9e-8, 3.9e-8 — the suite takes P5 (docs/benchmarks.md, "Test time").
  const auto exact = modes::ellipsoid_modes(1.0, 0.8, 0.6, 0.0);
  // The closed form's own check: λ² = 4a²b²/((a² + c²)(b² + c²)) upright (docs/volume.md §3).
  EXPECT_NEAR(exact.lambda, 2 * 0.8 / std::sqrt((1 + 0.36) * (0.64 + 0.36)), 1e-15);
  check_ellipsoid(ellipsoid_table(1.0, 0.8, 0.6, 0.0, 5, 0.5, 0.15), exact, 1e-5, 1e-6, 1e-6);
}

TEST(VolumeModes, TiltedEllipsoidIsTheClosedForm) {
  // Turned 30° about x: the spin-over mode now couples to all three axes (complex off-diagonal H), and the
  // geostrophic vortex to the transverse ones.
  const double tilt = std::numbers::pi / 6;
  const auto exact = modes::ellipsoid_modes(1.0, 0.8, 0.6, tilt);
  EXPECT_GT(std::abs(exact.H(1, 2)), 1e-2 * exact.H.trace().real());
  check_ellipsoid(ellipsoid_table(1.0, 0.8, 0.6, tilt, 4, 0.5, 0.15), exact, 5e-5, 5e-6, 5e-5);
}

// A user's CAD file (`cavity-modes volume FILE.brep|FILE.step`, gmsh's OpenCASCADE kernel; every volume fluid): the
// 1 : 0.8 : 0.6 ellipsoid written as BREP and as STEP by gmsh, read back and meshed as the built-in ellipsoid is, against
// the closed form.
TEST(VolumeModes, CadFileIsTheClosedForm) {
  const auto exact = modes::ellipsoid_modes(1.0, 0.8, 0.6, 0.0);
  for (const char* name : {"ellipsoid.brep", "ellipsoid.step"}) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    rc::geometry::load_gmsh();  // gmsh called directly, not through a GmshSession
    gmsh::initialize(0, nullptr, false);
    gmsh::model::add("cad");
    const int tag = gmsh::model::occ::addSphere(0, 0, 0, 1);
    gmsh::model::occ::dilate({{3, tag}}, 0, 0, 0, 1.0, 0.8, 0.6);
    gmsh::model::occ::synchronize();
    gmsh::write(file.string());
    gmsh::finalize();
    modes::VolumeTableRequest r;
    r.shape = {"volume", {}, file, 0.0};
    r.mesh.order = 4;
    r.mesh.size = 0.5;
    r.mesh.wall_size = 0.15;
    r.mesh.wall_growth = 1.0;
    std::printf("%s:\n", name);
    check_ellipsoid(modes::make_volume_table(r), exact, 5e-5, 5e-6, 5e-5);
    std::filesystem::remove(file);
  }
}

// `volume FILE --tilt`: the spheroid a = b = 1, c = 0.5 of data/volumes/spheroid.geo turned 30° about x, against the
// closed form of the tilted spheroid (its spin-over couples to all three axes; its frequency moves with the tilt), and
// against the same file untilted: the mesh is turned whole after meshing, so the sum rule's tensor (the geometry's:
// inertia less Zhukovsky's) must be the untilted one turned, to rounding.
TEST(VolumeModes, TiltedFileIsTheClosedForm) {
  const double tilt = std::numbers::pi / 6;
  modes::VolumeTableRequest r;
  r.shape = {"volume", {}, std::filesystem::path(RC_VOLUMES_DIR) / "spheroid.geo", tilt};
  r.mesh.order = 4;
  r.mesh.size = 0.5;
  r.mesh.wall_size = 0.15;
  r.mesh.wall_growth = 1.0;
  const auto exact = modes::ellipsoid_modes(1.0, 1.0, 0.5, tilt);
  EXPECT_GT(std::abs(exact.H(1, 2)), 1e-2 * exact.H.trace().real());
  const modes::VolumeTableResult tilted = modes::make_volume_table(r);
  check_ellipsoid(tilted, exact, 5e-5, 2e-5, 5e-5);
  r.shape.tilt = 0;
  const modes::VolumeTableResult upright = modes::make_volume_table(r);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d P = tensor(upright.table.volume_cavity.sum_rule), Pt = tensor(tilted.table.volume_cavity.sum_rule);
  const double turned = (Pt - R * P * R.transpose()).cwiseAbs().maxCoeff() / P.trace();
  std::printf("  the tilted file's sum rule tensor against the upright one's turned: %.1e\n", turned);
  EXPECT_LT(turned, 1e-10);
}

TEST(VolumeModes, SpheroidIsTheAxisymmetricTable) {
  // A spheroid meshed in 3-D against the axisymmetric (meridian) table of the same cavity: λ and E.
  modes::TableRequest req;
  req.shape = {"spheroid", {{"a", 1.0}, {"c", 0.5}}, {}};
  req.mesh = modes::mesh_method_defaults(req.shape, req.mesh);
  req.check_convergence = false;
  const ModeTable axi = modes::compute_mode_table(req);
  const auto three_d = ellipsoid_table(1.0, 1.0, 0.5, 0.0, 4, 0.5, 0.12);
  const ModeTable& t = three_d.table;
  ASSERT_GE(axi.size(), 1u);
  ASSERT_GE(t.size(), 1u);
  // The 3-D mesh has no axial symmetry: it splits the mode among discrete copies within 1e-3 (docs/volume.md §3).
  double E = 0, weighted = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::abs(t.lambda[i] - axi.lambda[0]) < 1e-3 * axi.lambda[0]) E += t.E[i], weighted += t.E[i] * t.lambda[i];
  const double lambda = weighted / E;
  const double dl = std::abs(lambda - axi.lambda[0]) / axi.lambda[0], dE = std::abs(E - axi.E[0]) / axi.E[0];
  std::printf("  axisymmetric lambda %.12f E %.12f; 3-D (%ld dofs) lambda %.12f E %.12f: %.1e, %.1e; J_zh %.1e\n",
              axi.lambda[0], axi.E[0], t.ndof, lambda, E, dl, dE, std::abs(t.J_zh - axi.J_zh) / axi.J_zh);
  EXPECT_LT(dl, 1e-5);
  EXPECT_LT(dE, 5e-5);
  EXPECT_LT(std::abs(t.J_zh - axi.J_zh), 1e-5 * axi.A_f);
  EXPECT_LT(std::abs(t.A_f - axi.A_f), 1e-5 * axi.A_f);
}

TEST(VolumeModes, SurveyIsThePressureEigenproblem) {
  // The survey (velocity space, block Lanczos) against the pencil λ²M + 2λ iG − 4Kz itself (pressure space, SLEPc
  // spectrum slicing in a window around the survey's λ, couplings from each eigenvector by volume_coupling.hpp), on one
  // mesh of a tilted ellipsoid: the same cluster λ and coupling tensor.
  geometry::VolumeShapeSpec shape{"ellipsoid", {{"a", 1.0}, {"b", 0.8}, {"c", 0.6}}, {}, 0.4};
  geometry::MeshOptions mesh{4, 0.5};
  mesh.wall_size = 0.15;
  mesh.wall_growth = 1.0;
  modes::VolumeSpace space(geometry::mesh_volume(shape, mesh));
  const auto fluid = modes::integrate_volume(space);
  const auto forms = modes::assemble_volume_forms(space);
  const modes::StiffnessSolver M(forms.M);
  const modes::VolumeVelocity V(space, fluid.centroid);
  modes::VolumeSurveySettings settings;
  settings.floor = 1e-7;  // every eigenpair that the pencil's window holds, but for a few 1e-7 of the weight
  const auto survey = modes::survey_volume_modes(V, M, forms, settings);
  ASSERT_FALSE(survey.modes.empty());
  const auto& top = survey.modes.front();
  const double half = 1e-3 * top.lambda;
  modes::VolumeMode m;  // the survey's modes in the window, summed
  double survey_weighted = 0;
  for (const auto& x : survey.modes)
    if (std::abs(x.lambda - top.lambda) < half) m.H += x.H, survey_weighted += x.H.trace().real() * x.lambda;
  m.lambda = survey_weighted / m.H.trace().real();
  const auto pencil = modes::real_form_pencil(forms);
  modes::QepSettings qs;
  qs.keep_eigenvectors = true;
  const auto pairs = modes::QuadraticEigenSolver(pencil, qs).solve_interval(top.lambda - half, top.lambda + half);
  Eigen::Matrix3cd H = Eigen::Matrix3cd::Zero();
  double weighted = 0;
  for (const auto& p : pairs.pairs) {  // each complex mode twice in the real form: half each
    const Eigen::Matrix3cd h = 0.5 * modes::pressure_mode_coupling(space, fluid.centroid, p.lambda, p.p).tensor();
    H += h;
    weighted += h.trace().real() * p.lambda;
  }
  const double lambda = weighted / H.trace().real();
  const double dl = std::abs(lambda - m.lambda) / m.lambda, dH = max_abs(H - m.H) / m.H.trace().real();
  std::printf("  %d dofs, window of 1e-3 about %.9f: survey (%zu modes) lambda %.12f, pencil (%zu eigenpairs) "
              "%.12f: %.1e; H %.1e (of which the survey's floor leaves out %.1e)\n",
              space.ndof(), top.lambda, survey.modes.size(), m.lambda, pairs.pairs.size(), lambda, dl, dH,
              (H - m.H).trace().real() / m.H.trace().real());
  EXPECT_LT(dl, 1e-9);
  EXPECT_LT(dH, 1e-6);  // the light eigenpairs below the floor
}

TEST(VolumeModes, ZhukovskyTensorIsTheClosedForm) {
  // Zhukovsky's tensor alone, P4 on a coarse mesh: J_zh = m (p² − q²)²/(5(p² + q²)) on each principal axis.
  const auto exact = modes::ellipsoid_modes(1.0, 0.7, 0.5, 0.0);
  geometry::VolumeShapeSpec shape{"ellipsoid", {{"a", 1.0}, {"b", 0.7}, {"c", 0.5}}, {}, 0.0};
  modes::VolumeSpace space(geometry::mesh_volume(shape, {4, 0.25}));
  const auto fluid = modes::integrate_volume(space);
  const auto forms = modes::assemble_volume_forms(space);
  const modes::StiffnessSolver M(forms.M);
  const modes::VolumeVelocity V(space, fluid.centroid);
  const auto J = modes::zhukovsky_tensor(V, M);
  double err = 0;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) err = std::max(err, std::abs(J[j][k] - exact.zhukovsky(j, k)));
  std::printf("  J_zh diagonal %.10f %.10f %.10f, max error %.1e of trace %.4f\n", J[0][0], J[1][1], J[2][2], err,
              exact.zhukovsky.trace());
  EXPECT_LT(err, 1e-4 * exact.zhukovsky.trace());
}
