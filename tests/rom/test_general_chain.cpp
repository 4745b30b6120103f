// The chain without axial symmetry (rom/general/, docs/rom.md "Bodies and tanks without axial symmetry") against
// (a) the axisymmetric chain (26) it must reproduce, (b) Euler's and Poisson's equations of a heavy rigid body with
// A ≠ B, and (c) the Poincaré–Hough top: a shell with an ellipsoidal cavity of ideal fluid in uniform vorticity, its
// linearised equations written independently of the modal table (Poincaré 1910; Hough 1895; docs/volume.md §3).
#include "bench.hpp"
#include "ellipsoid_table.hpp"
#include "frequency_response.hpp"
#include "general_chain.hpp"
#include "general_response.hpp"
#include "general_run.hpp"
#include "general_system.hpp"
#include "linear_validity.hpp"
#include "nonlinear_run.hpp"
#include "sweep.hpp"
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <cstdio>
#include <numbers>

namespace rc::rom::test {
namespace {

using Roots = std::vector<std::complex<double>>;

Eigen::Matrix3d cross(const Eigen::Vector3d& u) {  // [u]× x = u × x
  Eigen::Matrix3d m;
  m << 0, -u(2), u(1), u(2), 0, -u(0), -u(1), u(0), 0;
  return m;
}

Roots general_roots(const std::string& text) {
  return general_spectrum(build_general_chain(parse_scene_text(text, test_dir(), "test-scene"))).roots;
}

// σ = −i eig(M⁻¹A) of M ẋ = A x.
Roots roots_of_pencil(const Eigen::MatrixXd& M, const Eigen::MatrixXd& A) {
  // A plain matrix, not the solve's expression: EigenSolver's compute() for a MatrixXd is compiled once in
  // common/ (eigen_dense.hpp); for an expression type this file would compile the whole algorithm again.
  const Eigen::MatrixXd B = M.partialPivLu().solve(A);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(B, false);
  Roots r;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
    r.emplace_back(es.eigenvalues()[i].imag(), -es.eigenvalues()[i].real());
  return r;
}

std::string axisymmetric_chain(bool free_chain, double spin) {
  std::vector<Body> b(3);
  b[0].table = spheroid_file(1, 0.6);
  b[0].density = 900;
  b[0].center = 0.2;
  b[2].table = "four_modes.h5";
  if (!std::filesystem::exists(test_dir() / b[2].table)) write_table(four_mode_table(), test_dir() / b[2].table);
  b[1].A = 0.2;
  b[1].C = 0.3;
  for (Body& x : b) x.spin = spin;
  return scene_text(b, {{2.0, 0.01}, {1.5, 0.0}}, 9.81, free_chain, 0.02);
}

TEST(GeneralChain, ReproducesTheAxisymmetricChain) {
  for (const bool free_chain : {false, true})
    for (const double spin : {30.0, -12.0}) {
      const std::string text = axisymmetric_chain(free_chain, spin);
      const Roots expected = turned(roots_of(compute_spectrum(model_of(text))), spin);
      const Roots got = general_roots(text);
      const double err = root_set_distance(got, expected, spectral_radius(expected));
      std::printf("axisymmetric chain (%s, spin %g): %zu roots, largest distance %.2e of the spectral radius\n",
                  free_chain ? "free" : "fixed", spin, got.size(), err);
      EXPECT_LT(err, 1e-11);
    }
}

// A heavy rigid body on a fixed point, its principal axes turned by the products of inertia, spinning about its axis
// (Euler and Poisson in its frame): I δω̇ + ω0 e_z × I δω − (I ω0 e_z) × δω = −m g c e_z × δγ, δγ̇ = −ω0 e_z × δγ + e_z × δω.
Roots euler_poisson(const Eigen::Matrix3d& I, double w, double mgc) {
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(6, 6), A = Eigen::MatrixXd::Zero(6, 6);
  M.topLeftCorner<3, 3>() = I;
  A.topLeftCorner<3, 3>() = -w * cross(ez) * I + cross(I * w * ez);
  A.topRightCorner<3, 3>() = -mgc * cross(ez);
  A.bottomLeftCorner<3, 3>() = cross(ez);
  A.bottomRightCorner<3, 3>() = -w * cross(ez);
  return drop_smallest(roots_of_pencil(M, A), 2);  // δω_z and δγ_z: the spin's own zeros
}

TEST(GeneralChain, HeavyBodyWithUnequalMomentsIsEulerPoisson) {
  // A ≠ B with a product I_xy: C the largest moment (a fast top sleeps: every root real), then C between the
  // transverse principal moments (0.0741, 0.1259: the intermediate axis, unstable at any spin).
  struct Case { double C; bool stable; };
  for (const Case& k : {Case{0.2, true}, Case{0.1, false}}) {
    const double A = 0.12, B = 0.08, Ixy = 0.01, m = 2, com = 0.15, g = 9.81, spin = 25;
    const std::string text = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 2\nA = 0.12\nB = 0.08\n"
                             "Ixy = 0.01\nC = " + num(k.C) + "\ncom = 0.15\nspin = " + num(spin) + "\n";
    Eigen::Matrix3d I;
    I << A, Ixy, 0, Ixy, B, 0, 0, 0, k.C;  // the scene's moments are about the fixed point O
    const Roots expected = euler_poisson(I, spin, m * g * com);
    const GeneralSpectrum sp = general_spectrum(build_general_chain(parse_scene_text(text, test_dir(), "t")));
    const double err = root_set_distance(sp.roots, expected, spectral_radius(expected));
    std::printf("heavy body A %g B %g Ixy %g C %g spin %g: %s, growth %.4g 1/s, roots against Euler-Poisson %.2e\n",
                A, B, Ixy, k.C, spin, sp.verdict.stable ? "stable" : "unstable", sp.verdict.growth, err);
    EXPECT_LT(err, 1e-12);
    EXPECT_EQ(sp.verdict.stable, k.stable);
  }
}

// (c) The Poincaré–Hough top: a shell (tensor I_s about O) with ellipsoidal cavities (semi-axes a, b, c, each turned
// by `tilt` about x, its centre at `at`) of ideal fluid, spinning at ω0 about z, gravity on the total mass. Each fluid
// in its ellipsoid's frame (R: ellipsoid → body): V = D(ω_f × D⁻¹r), its angular momentum R Hf ω_f (the same about any
// point: the flow carries no momentum), Hf = (2m/5) diag(bc, ac, ab), its vorticity K ω_f obeying
// K ω̇_f = −2ω0 D [D⁻¹Ω]× ω_f − 2 Rᵀ δω̇ (the uniform translation of an off-axis tank only adds a pressure gradient).
struct Tank {
  double a = 1, b = 0.8, c = 0.6, tilt = 0;
  Eigen::Vector3d at{0, 0, 0.05};
};
struct Top {
  std::vector<Tank> tanks{Tank{}};
  double rho = 1000, L = 0.1;
  double mass = 3, com = 0.1, A = 0.2, B = 0.15, C = 0.12, spin = 20, g = 9.81;
};

Eigen::Matrix3d rotation(double tilt) { return Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix(); }

// A tank's mass and frozen tensor about O in the body frame (SI units): the parallel-axis theorem in 3-D.
Eigen::Matrix3d frozen_fluid(const Top& top, const Tank& t, double& mf) {
  const double a = t.a * top.L, b = t.b * top.L, c = t.c * top.L;
  mf = top.rho * 4 * std::numbers::pi * a * b * c / 3;
  const Eigen::Matrix3d R = rotation(t.tilt);
  return R * (mf / 5 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b)).asDiagonal() * R.transpose() +
         mf * (t.at.squaredNorm() * Eigen::Matrix3d::Identity() - t.at * t.at.transpose());
}

// The shell's products that balance the tanks' (Ixz, Iyz) and the body's tensor with its frozen fluid.
Eigen::Matrix3d body_inertia(const Top& top, Eigen::Vector2d& balance, double& mgc) {
  Eigen::Matrix3d If = Eigen::Matrix3d::Zero();
  mgc = top.mass * top.com;
  for (const Tank& t : top.tanks) {
    double mf = 0;
    If += frozen_fluid(top, t, mf);
    mgc += mf * t.at.z();
  }
  mgc *= top.g;
  balance = Eigen::Vector2d(-If(0, 2), -If(1, 2));
  Eigen::Matrix3d Is;
  Is << top.A, 0, balance(0), 0, top.B, balance(1), balance(0), balance(1), top.C;
  return Is + If;
}

Roots poincare_hough(const Top& top) {
  Eigen::Vector2d balance;
  double mgc = 0;
  const Eigen::Matrix3d I = body_inertia(top, balance, mgc);
  const int nt = static_cast<int>(top.tanks.size()), dim = 6 + 3 * nt, g0 = 3 + 3 * nt;  // δω, ω_f per tank, δγ
  const double w = top.spin;
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(dim, dim), A = Eigen::MatrixXd::Zero(dim, dim);
  M.block<3, 3>(0, 0) = I;
  A.block<3, 3>(0, 0) = -w * cross(ez) * I + cross(I * w * ez);
  A.block<3, 3>(0, g0) = -mgc * cross(ez);
  A.block<3, 3>(g0, 0) = cross(ez);
  A.block<3, 3>(g0, g0) = -w * cross(ez);
  for (int i = 0; i < nt; ++i) {
    const Tank& t = top.tanks[i];
    double mf = 0;
    frozen_fluid(top, t, mf);
    const double a = t.a * top.L, b = t.b * top.L, c = t.c * top.L;
    const Eigen::Matrix3d R = rotation(t.tilt);
    const Eigen::Vector3d d(a, b, c), Omega = R.transpose() * ez;
    const Eigen::Matrix3d D = d.asDiagonal(), Dinv = d.cwiseInverse().asDiagonal();
    const Eigen::Matrix3d K = Eigen::Vector3d((b * b + c * c) / (b * c), (a * a + c * c) / (a * c),
                                              (a * a + b * b) / (a * b)).asDiagonal();
    const Eigen::Matrix3d Hf = (2 * mf / 5 * Eigen::Vector3d(b * c, a * c, a * b)).asDiagonal();
    const int f = 3 + 3 * i;
    M.block<3, 3>(0, f) = R * Hf;
    M.block<3, 3>(f, 0) = 2 * R.transpose();
    M.block<3, 3>(f, f) = K;
    A.block<3, 3>(0, f) = -w * cross(ez) * R * Hf;
    A.block<3, 3>(f, f) = -2 * w * D * cross(Dinv * Omega);
  }
  // δγ_z and each geostrophic vortex's level: zeros of their own.
  return drop_smallest(roots_of_pencil(M, A), 1 + static_cast<std::size_t>(nt));
}

// The same top as a scene, each tank the closed form's table (docs/volume.md §5), written as cavity-modes writes one.
std::string top_scene(const Top& top) {
  Eigen::Vector2d balance;
  double mgc = 0;
  body_inertia(top, balance, mgc);
  std::ostringstream os;
  os << "[system]\nkind = \"fixed\"\ngravity = " << num(top.g) << "\n[[body]]\nmass = " << num(top.mass)
     << "\nA = " << num(top.A) << "\nB = " << num(top.B) << "\nC = " << num(top.C) << "\nIxz = " << num(balance(0))
     << "\nIyz = " << num(balance(1)) << "\ncom = " << num(top.com) << "\nspin = " << num(top.spin) << "\n";
  for (const Tank& t : top.tanks) {
    const std::string name = "ellipsoid_" + num(t.a) + "_" + num(t.b) + "_" + num(t.c) + "_" + num(t.tilt) + ".h5";
    write_table(ellipsoid_table(t.a, t.b, t.c, t.tilt), test_dir() / name);
    os << "[[body.cavity]]\ntable = \"" << name << "\"\ndensity = " << num(top.rho) << "\nscale = " << num(top.L)
       << "\ncenter = " << num(t.at.z()) << "\noffset = [" << num(t.at.x()) << ", " << num(t.at.y()) << "]\n";
  }
  return os.str();
}

TEST(GeneralChain, PoincareHoughTopIsTheClosedForm) {
  std::vector<Top> tops(5);
  tops[1].tanks[0].tilt = 0.5;             // the tank tilted: the tilt and the spin coupled through the fluid
  tops[2].g = 0;                           // free (no gravity): the steady tilt's roots ±ω0
  tops[3].spin = 3;                        // slow: the heavy top falls
  tops[3].A = 0.05;
  tops[3].B = 0.04;
  // A spacecraft's two tanks off the axis, on opposite sides (the centre of mass stays on the axis), one tilted and
  // one a different ellipsoid turned the other way: their products cancel only with the shell's balance.
  Tank left, right;
  left.at = Eigen::Vector3d(0.15, 0.05, 0.08);
  right.at = -left.at + Eigen::Vector3d(0, 0, 2 * 0.08);
  left.tilt = 0.3;
  right = Tank{1, 0.8, 0.6, -0.3, right.at};
  tops[4].tanks = {left, right};
  for (const Top& t : tops) {
    const Roots expected = poincare_hough(t);
    const GeneralSpectrum sp = general_spectrum(build_general_chain(parse_scene_text(top_scene(t), test_dir(), "t")));
    const double err = root_set_distance(sp.roots, expected, spectral_radius(expected));
    std::printf("Poincare-Hough top (%zu tank%s, first tilted %g, g %g, spin %g): %zu roots, growth %.4g 1/s, against "
                "the closed form %.2e\n", t.tanks.size(), t.tanks.size() > 1 ? "s off the axis" : "", t.tanks[0].tilt,
                t.g, t.spin, sp.roots.size(), sp.verdict.growth, err);
    EXPECT_LT(err, 1e-10);
    EXPECT_EQ(sp.verdict.stable, t.spin > 10);  // the slow heavy top falls
  }
}

// `chain-rom response` on the general chain (general_response.hpp): on an axisymmetric chain its tilt A₊ is (26)'s
// (frequency_response.hpp, from the characteristic matrix, an independent formula) and its mirror A₋ vanishes.
TEST(GeneralChain, FrequencyResponseIsTheAxisymmetricChains) {
  for (const bool free_chain : {false, true}) {
    const std::string text = axisymmetric_chain(free_chain, 30.0);
    for (int body = 0; body < 3; body += 2) {
      const FrequencyResponse expected = frequency_response(model_of(text), body, -40.0, 55.0, 39);
      const GeneralFrequencyResponse got =
          general_frequency_response(build_general_chain(parse_scene_text(text, test_dir(), "t")), body, -40.0, 55.0, 39);
      double err = 0, mirror = 0;
      for (Eigen::Index i = 0; i < expected.tilt.rows(); ++i) {
        err = std::max(err, (got.tilt.row(i) - expected.tilt.row(i)).norm() / expected.tilt.row(i).norm());
        mirror = std::max(mirror, got.mirror.row(i).norm() / expected.tilt.row(i).norm());
      }
      std::printf("axisymmetric chain (%s), moment on body %d, 39 frequencies: tilt against (26)'s %.2e, mirror "
                  "%.2e (relative)\n", free_chain ? "free" : "fixed", body + 1, err, mirror);
      EXPECT_LT(err, 1e-9);
      EXPECT_LT(mirror, 1e-12);
    }
  }
}

// Without axial symmetry (the Poincaré–Hough top: B ≠ A and a tilted ellipsoidal tank of ideal fluid) there is no
// (26) to compare with; what must hold is that the steady response of a conservative chain takes no net work from
// the harmonic moment (mean power −½ Ω Im(f̂ᴴ q̂) = 0 on the moment's body), while the asymmetry shows as a mirror
// tilt A₋ ≠ 0.
TEST(GeneralChain, FrequencyResponseOfAConservativeChainTakesNoWork) {
  Top top;
  top.tanks[0].tilt = 0.5;
  const GeneralChain g = build_general_chain(parse_scene_text(top_scene(top), test_dir(), "t"));
  const GeneralFrequencyResponse r = general_frequency_response(g, 0, -70.0, 50.0, 41);
  double work = 0, mirror = 0;
  for (std::size_t i = 0; i < r.sigma.size(); ++i) {
    // q̂ from A₊ and A₋: q̂_x − i q̂_y = 2A₊, q̂_x + i q̂_y = 2 conj(A₋); the force f̂ = (1, i).
    const std::complex<double> ap = r.tilt(i, 0), am = std::conj(r.mirror(i, 0)), I(0, 1);
    const std::complex<double> qx = ap + am, qy = I * (ap - am);
    const std::complex<double> fq = qx + std::conj(I) * qy;  // f̂ᴴ q̂ with f̂ = (1, i)
    work = std::max(work, std::abs(fq.imag()) / (std::abs(qx) + std::abs(qy)));
    mirror = std::max(mirror, std::abs(r.mirror(i, 0)) / std::abs(r.tilt(i, 0)));
  }
  std::printf("Poincare-Hough top, 41 frequencies: mean work / |f||q| at most %.2e, mirror tilt up to %.3g of the "
              "tilt, %zu resonances in the range\n", work, mirror, r.resonances.size());
  EXPECT_LT(work, 1e-10);
  EXPECT_GT(mirror, 1e-3);
  EXPECT_GT(r.resonances.size(), 0u);
}

// Bodies at different spins: an axisymmetric chain through the general chain must give (26)'s roots, which take each
// body's own spin (the frame turns at body[1]'s; the others' spins enter only through their gyroscopic terms).
TEST(GeneralChain, AxisymmetricBodiesAtTheirOwnSpinsAreTheAxisymmetricChain) {
  for (const bool free_chain : {false, true}) {
    std::vector<Body> b(3);
    b[1].A = 0.2;
    b[1].C = 0.3;
    b[0].spin = 30;
    b[1].spin = -12;
    b[2].spin = 55;
    const std::string text = scene_text(b, {{2.0, 0.01}, {1.5, 0.0}}, 9.81, free_chain, 0.02);
    const Roots expected = turned(roots_of(compute_spectrum(model_of(text))), 30.0);
    const Roots got = general_roots(text);
    const double err = root_set_distance(got, expected, spectral_radius(expected));
    std::printf("three bodies at 30, -12 and 55 rad/s (%s): %zu roots, largest distance %.2e of the spectral radius\n",
                free_chain ? "free" : "fixed", got.size(), err);
    EXPECT_LT(err, 1e-11);
  }
}

// `sweep` over the spin of the heavy top with A ≠ B: every point's verdict is Euler–Poisson's (sleeping above the
// threshold spin, falling below it).
TEST(GeneralChain, SweepIsEulerPoissonAtEveryPoint) {
  const double A = 0.12, B = 0.08, Ixy = 0.01, C = 0.2, m = 2, com = 0.15, g = 9.81;
  const std::string text = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 2\nA = 0.12\nB = 0.08\n"
                           "Ixy = 0.01\nC = 0.2\ncom = 0.15\nspin = 10\n";
  const Scene scene = parse_scene_text(text, test_dir(), "t");
  TableCache tables;
  const SweepAxis axis{parse_param_key("body[1].spin", scene), 2, 32, 31};
  const SweepResult r = run_sweep(scene, tables, axis, std::nullopt, 2, {}, true);
  Eigen::Matrix3d I;
  I << A, Ixy, 0, Ixy, B, 0, 0, 0, C;
  int stable = 0, agree = 0;
  for (const SweepPoint& p : r.points) {
    ASSERT_TRUE(p.ok) << p.error;
    const Roots ep = euler_poisson(I, p.v1, m * g * com);
    double margin = 0;
    for (const auto& z : ep) margin = std::max(margin, std::abs(z.imag()));
    const bool ep_stable = margin <= kRealTolerance * spectral_radius(ep);
    stable += p.verdict.stable;
    agree += p.verdict.stable == ep_stable;
  }
  std::printf("heavy top A != B, spin 2..32 rad/s: %d of %zu points stable, %d agree with Euler-Poisson\n", stable,
              r.points.size(), agree);
  EXPECT_EQ(agree, static_cast<int>(r.points.size()));
  EXPECT_GT(stable, 0);
  EXPECT_LT(stable, static_cast<int>(r.points.size()));
}

// `run`: (i) a heavy top with B ≠ A and a spheroidal tank, released at a small tilt, against the nonlinear chain
// (rigid bodies at any angle with their own tank model): the difference falls as the amplitude squared; (ii) the
// spacecraft with two tilted tanks off its axis keeps its angular momentum in space.
// The general chain's run against the nonlinear chain (linear_validity) for the scene of each amplitude, 0.02 and 0.01
// rad: below `limit` of the largest tilt, and 4 times less at half the amplitude (the amplitude squared).
void expect_quadratic_validity(const std::function<std::string(double)>& scene_at, const char* what, double limit) {
  double previous = 0;
  for (const double amplitude : {0.02, 0.01}) {
    const Scene scene = parse_scene_text(scene_at(amplitude), test_dir(), "t");
    const GeneralChain g = build_general_chain(scene);
    ASSERT_TRUE(general_spectrum(g).verdict.stable);
    const LinearValidity v = linear_validity(scene, propagate_general(g, scene).u);
    ASSERT_TRUE(v.measured) << v.why_not;
    std::printf("%s, tilt %g rad: the general run against the nonlinear chain %.3e of the largest tilt%s\n", what,
                amplitude, v.difference,
                previous > 0 ? (", " + std::to_string(previous / v.difference) + " times less at half the amplitude").c_str() : "");
    EXPECT_LT(v.difference, limit);
    if (previous > 0) {
      EXPECT_GT(previous / v.difference, 3.5);  // the amplitude squared: 4
      EXPECT_LT(previous / v.difference, 4.5);
    }
    previous = v.difference;
  }
}

// A projectile's aerodynamic moments — the static moment, pitch damping and the Magnus moment (−i M_p ω in the
// stiffness) — and a constant axial field are isotropic about the spin axis: (26)'s terms carried into the turning
// frame. An axisymmetric shell with a tank through the general chain must give (26)'s roots, overturning (the slow arm
// grows) and fin-stabilised.
std::string shell(double static_moment, double B, const std::string& rest = "") {
  return "[system]\nkind = \"fixed\"\ngravity = 0.0\n[field]\nspace = [0.0, 0.0, -4.0]\n[[body]]\nmass = 2.0\n"
         "A = 0.025\nB = " + num(B) + "\nC = 0.012\ncom = 0.02\nspin = 400.0\n[body.aero]\nstatic_moment = " +
         num(static_moment) + "\npitch_damping = 0.002\nmagnus = 2e-6\n[body.cavity]\ntable = \"" + spheroid_file(1, 0.6) +
         "\"\ndensity = 1000\nscale = 0.03\ncenter = 0.01\n" + rest;
}

TEST(GeneralChain, AerodynamicMomentsAndAxialFieldAreTheAxisymmetricChains) {
  for (const double static_moment : {4.0, -4.0}) {
    const std::string text = shell(static_moment, 0.025);
    const ChainModel m = model_of(text);
    ASSERT_TRUE(m.has_circulatory());
    const Roots expected = turned(roots_of(compute_spectrum(m)), 400.0);
    const Roots got = general_roots(text);
    const double err = root_set_distance(got, expected, spectral_radius(expected));
    const Verdict v26 = compute_verdict(m);
    const GeneralSpectrum gs = general_spectrum(build_general_chain(parse_scene_text(text, test_dir(), "t")));
    std::printf("shell with a tank, %s (M_alpha %g N m), pitch damping, Magnus, axial field: %zu roots against (26)'s "
                "%.2e of the spectral radius; growth %.6g and %.6g 1/s\n", static_moment > 0 ? "overturning" : "fin-stabilised",
                static_moment, got.size(), err, gs.verdict.growth, v26.growth);
    EXPECT_LT(err, 1e-11);
    EXPECT_EQ(gs.verdict.stable, v26.stable);
  }
}

// The fin-stabilised shell with B ≠ A: its linear run against the nonlinear chain (which takes the aerodynamic moments
// as M_α e_z × n, −M_q Ω_⊥ and M_p s (n − n_z e_z) at any yaw), the difference falling as the amplitude squared.
TEST(GeneralChain, AsymmetricShellRunIsTheNonlinearChainAtSmallAmplitude) {
  expect_quadratic_validity([](double amplitude) {
    return shell(-4.0, 0.03, "[initial]\ntilt = [[" + num(amplitude) + ", 0.0]]\nrate = [[0.0, " + num(amplitude) +
                              "]]\n[run]\nt_end = 0.3\noutput_step = 0.0005\n");
  }, "fin-stabilised shell B != A with a tank, aerodynamic moments and an axial field", 2e-3);
}

// External moments and forces drive the chain without entering its roots (they never enter the matrices, so that is
// not asserted): `spectrum` takes the scene, a linear run refuses it naming the key and the nonlinear model.
TEST(GeneralChain, ExternalMomentsAreRefusedByALinearRun) {
  const std::string quiet = shell(-4.0, 0.03, "[initial]\ntilt = [[0.01, 0.0]]\n[run]\nt_end = 0.1\noutput_step = 0.001\n");
  std::string driven = quiet;
  driven.insert(driven.find("[body.aero]"), "[body.moment]\nspace = [0.01, 0.0, 0.0]\n");
  EXPECT_FALSE(general_roots(driven).empty());
  const Scene scene = parse_scene_text(driven, test_dir(), "t");
  std::string what;
  try {
    propagate_general(build_general_chain(scene), scene);
  } catch (const SceneError& e) {
    what = e.what();
  }
  std::printf("a linear run with an external moment: %s\n", what.c_str());
  // A field varying in space acts on the whole inertia tensor (anisotropic with B ≠ A): refused in every command.
  std::string graded = quiet;
  graded.replace(graded.find("space = [0.0, 0.0, -4.0]"), 24, "space = [0.0, 0.0, -4.0]\ngradient = [[-1.0, 0.0, 0.0], "
                 "[0.0, -1.0, 0.0], [0.0, 0.0, 2.0]]");
  std::string gradient_refusal;
  try {
    build_general_chain(parse_scene_text(graded, test_dir(), "t"));
  } catch (const SceneError& e) {
    gradient_refusal = e.what();
  }
  EXPECT_NE(gradient_refusal.find("field.gradient: a field varying in space acts on a body's whole inertia tensor"),
            std::string::npos) << gradient_refusal;
  EXPECT_NE(what.find("body[1].moment: an external moment drives the chain"), std::string::npos) << what;
  EXPECT_NE(what.find("model = \"nonlinear\""), std::string::npos) << what;
}

TEST(GeneralChain, RunIsTheNonlinearChainAtSmallAmplitude) {
  expect_quadratic_validity([](double amplitude) {
    return "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 2\nA = 0.05\nB = 0.06\nC = 0.08\ncom = 0.05\n"
           "spin = 200\n[body.cavity]\ntable = \"" + spheroid_file(1, 0.6) + "\"\ndensity = 1000\nscale = 0.04\n"
           "center = 0.05\n[initial]\ntilt = [[" + num(amplitude) + ", 0.0]]\nrate = [[0.0, " + num(amplitude) +
           "]]\n[run]\nt_end = 0.5\noutput_step = 0.001\n";
  }, "B != A top with a tank", 2e-3);
}

// A dual-spin craft: a platform without axial symmetry (B ≠ A, a tilted 3-D tank) and a rotor, axisymmetric and
// without tanks, spinning at its own rate on top of it. In the platform's frame the coefficients are constant; the
// linear run must be the nonlinear chain (a separate model that takes any spins) at small amplitude, the difference
// falling as the amplitude squared.
TEST(GeneralChain, DualSpinRunIsTheNonlinearChainAtSmallAmplitude) {
  Top top;
  top.tanks[0].tilt = 0.5;
  std::string platform = top_scene(top);
  platform.insert(platform.find("spin = "), "next_joint = 0.2\n");
  expect_quadratic_validity([&](double amplitude) {
    return platform + "[[body]]\nmass = 1\nA = 0.01\nC = 0.015\ncom = 0.03\nspin = 150\n[[joint]]\n"
           "stiffness = 400.0\nfriction = 0.0\n[initial]\ntilt = [[" + num(amplitude) + ", 0.0], [" + num(amplitude) +
           ", 0.0]]\nrate = [[0.0, " + num(amplitude) + "], [0.0, 0.0]]\n[run]\nt_end = 0.5\noutput_step = 0.001\n";
  }, "dual-spin craft (platform B != A with a tilted tank at 20 rad/s, rotor at 150 rad/s)", 2e-3);
}

// The same craft with a rotor without axial symmetry (B ≠ A): two spins, periodic coefficients in every frame, the
// linear run by Magnus steps (floquet.hpp) against the nonlinear chain.
TEST(GeneralChain, AsymmetricRotorRunIsTheNonlinearChainAtSmallAmplitude) {
  Top top;
  top.tanks[0].tilt = 0.5;
  std::string platform = top_scene(top);
  platform.insert(platform.find("spin = "), "next_joint = 0.2\n");
  expect_quadratic_validity([&](double amplitude) {
    return platform + "[[body]]\nmass = 1\nA = 0.01\nB = 0.012\nC = 0.015\ncom = 0.03\nspin = 150\n[[joint]]\n"
           "stiffness = 400.0\nfriction = 0.0\n[initial]\ntilt = [[" + num(amplitude) + ", 0.0], [" + num(amplitude) +
           ", 0.0]]\nrate = [[0.0, " + num(amplitude) + "], [0.0, 0.0]]\n[run]\nt_end = 0.5\noutput_step = 0.001\n";
  }, "dual-spin craft with a rotor B != A (platform at 20 rad/s, rotor at 150 rad/s: periodic)", 2e-3);
}

TEST(GeneralChain, RunKeepsTheAngularMomentumOfAFreeBody) {
  Top craft;
  craft.g = 0;
  craft.C = 0.4;  // spinning about its largest moment: stable, so the integral is checked on a bounded motion
  Tank left, right;
  left.at = Eigen::Vector3d(0.15, 0.05, 0.08);
  left.tilt = 0.3;
  right = Tank{1, 0.8, 0.6, 0.3, Eigen::Vector3d(-0.15, -0.05, 0.08)};
  craft.tanks = {left, right};
  const std::string text = top_scene(craft) + "[initial]\ntilt = [[0.01, 0.004]]\nrate = [[0.05, -0.02]]\n"
                                              "[run]\nt_end = 5.0\noutput_step = 0.002\n";
  const Scene scene = parse_scene_text(text, test_dir(), "t");
  const GeneralChain g = build_general_chain(scene);
  ASSERT_TRUE(general_spectrum(g).verdict.stable);
  const GeneralHistory h = propagate_general(g, scene);
  const double spin_change = (h.spin.array() - craft.spin).abs().maxCoeff();
  std::printf("free body with two tilted tanks off its axis, 5 s: angular momentum drift %.2e, the spin moved by %.2e "
              "rad/s (the tanks tie it to the tilt)\n", h.momentum_drift, spin_change);
  EXPECT_LT(h.momentum_drift, 1e-11);
  EXPECT_GT(spin_change, 1e-6);  // the tilted tanks couple the spin to the tilt: the integral involves both
}

// `[initial] fluid` in the chain without axial symmetry (Batyr (9): the liquid's own initial motion): a free body with
// B != A and an axisymmetric tank started on the real part of one of its coupled eigenvectors — tilt, rate and the
// fluid's z(0) written as the scene's keys — must stay on it, y(t) = Re(e^{mu t} v) (the modal solution), which a
// fluid amplitude put anywhere else in the state, or with another phase, would leave at once; and started with the
// fluid alone in motion, the body's angular momentum perturbation (the fluid's h included) must keep its value.
TEST(GeneralChain, InitialFluidOnAnEigenvectorStaysOnIt) {
  const std::string body = "[system]\nkind = \"free\"\ngravity = 0.0\n[[body]]\nmass = 2.0\nA = 0.02\nB = 0.024\n"
                           "C = 0.04\ncom = 0.0\nspin = 30.0\n[body.cavity]\ntable = \"" + spheroid_file(1, 0.6) +
                           "\"\ndensity = 1000.0\nscale = 0.1\ncenter = 0.0\noffset = [0.0, 0.0]\n";
  const Scene bare = parse_scene_text(body, test_dir(), "t");
  const GeneralChain g = build_general_chain(bare);
  ASSERT_FALSE(g.axial);
  ASSERT_GE(g.n_modes(), 1);
  const GeneralSystem sys = build_general_system(g);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(sys.B, true);
  const int nq = 2 * g.n, d = g.dim_q(), z0 = nq + d;
  // The root whose eigenvector is most evenly shared between the body and the fluid, turning (Im mu > 0).
  int pick = -1;
  double best = 0;
  for (int j = 0; j < es.eigenvalues().size(); ++j) {
    const Eigen::VectorXcd v = es.eigenvectors().col(j);
    const double body_part = v.head(nq + d).norm(), fluid_part = v.tail(v.size() - z0).norm();
    const double shared = std::min(body_part, fluid_part) / v.norm();
    if (es.eigenvalues()[j].imag() > 1e-6 && shared > best) best = shared, pick = j;
  }
  ASSERT_GE(pick, 0);
  const std::complex<double> mu = es.eigenvalues()[pick];
  const Eigen::VectorXcd v = es.eigenvectors().col(pick) / es.eigenvectors().col(pick).cwiseAbs().maxCoeff();
  const Eigen::VectorXd y0 = v.real();
  // The state's layout (general_run.cpp): y = (s Re v, -s Im v, Re v', -Im v', Re z, Im z), v = e^{i w0 t} u in F.
  const std::complex<double> u0(y0[0] / sys.s, -y0[1] / sys.s), vdot(y0[nq], -y0[nq + 1]);
  const std::complex<double> udot = vdot - std::complex<double>(0, g.spin) * u0;
  std::string initial = "[initial]\ntilt = [[" + num(u0.real()) + ", " + num(u0.imag()) + "]]\nrate = [[" +
                        num(udot.real()) + ", " + num(udot.imag()) + "]]\nfluid = [";
  for (int l = 0; l < g.n_modes(); ++l)
    initial += std::string(l ? ", " : "") + "[" + num(y0[z0 + 2 * l]) + ", " + num(y0[z0 + 2 * l + 1]) + "]";
  initial += "]\n[run]\nt_end = 2.0\noutput_step = 0.01\n";
  const Scene scene = parse_scene_text(body + initial, test_dir(), "t");
  const GeneralHistory h = propagate_general(g, scene);
  double worst = 0, size = 0;
  for (std::size_t j = 0; j < h.t.size(); ++j) {
    const Eigen::VectorXd y = (std::exp(mu * h.t[j]) * v).real();
    const std::complex<double> u = std::exp(std::complex<double>(0, -g.spin * h.t[j])) * std::complex<double>(y[0], -y[1]) /
                                   sys.s;
    worst = std::max(worst, std::abs(h.u(j, 0) - u));
    size = std::max(size, std::abs(u));
    for (int l = 0; l < g.n_modes(); ++l) {
      const std::complex<double> z(y[z0 + 2 * l], y[z0 + 2 * l + 1]);
      worst = std::max(worst, std::abs(h.z(j, l) - z));
      size = std::max(size, std::abs(z));
    }
  }
  std::printf("started on the eigenvector of sigma = %.6f%+.2ei rad/s (%.2f of it in the fluid's share), %d fluid "
              "pairs: the run leaves the modal solution by %.1e of its size over %zu steps\n",
              mu.imag(), -mu.real(), best, g.n_modes(), worst / size, h.t.size());
  EXPECT_LT(worst, 1e-9 * size);
  EXPECT_GT(best, 0.05);  // a root that the fluid and the body share: a misplaced fluid state would show
  // The fluid alone in motion: the body starts at rest and takes up the fluid's angular momentum.
  const std::string alone = body + "[initial]\nfluid = [" + [&] {
    std::string f;
    for (int l = 0; l < g.n_modes(); ++l) f += std::string(l ? ", " : "") + (l ? "[0.0, 0.0]" : "[0.02, -0.01]");
    return f;
  }() + "]\n[run]\nt_end = 2.0\noutput_step = 0.01\n";
  const GeneralHistory ha = propagate_general(g, parse_scene_text(alone, test_dir(), "t"));
  const double moved = ha.u.cwiseAbs().maxCoeff();
  std::printf("the fluid alone in motion: the body tilts to %.2e rad, its angular momentum drifts %.1e\n", moved,
              ha.momentum_drift);
  EXPECT_GT(moved, 1e-6);
  EXPECT_LT(ha.momentum_drift, 1e-11);
  // One pair more than the kept modes: refused, naming the key.
  std::string wrong = body + "[initial]\nfluid = [[0.1, 0.0]";
  for (int l = 0; l < g.n_modes(); ++l) wrong += ", [0.1, 0.0]";
  wrong += "]\n[run]\nt_end = 1.0\noutput_step = 0.1\n";
  EXPECT_THROW(propagate_general(g, parse_scene_text(wrong, test_dir(), "t")), SceneError);
}

// The nonlinear chain with tanks without axial symmetry (volume_fluid.hpp): a heavy top whose shell has a product
// I_xy (taken in its principal axes) carrying two tilted tanks off its axis, released at 0.02 and 0.01 rad: against
// the general chain's exact run, the difference falls as the amplitude squared.
TEST(GeneralChain, NonlinearChainWithTiltedTanksIsTheGeneralRunAtSmallAmplitude) {
  Top top;
  top.C = 0.4;  // spinning about its largest moment
  top.tanks = {Tank{1, 0.8, 0.6, 0.3, Eigen::Vector3d(0.15, 0.05, 0.08)},
               Tank{1, 0.8, 0.6, 0.3, Eigen::Vector3d(-0.15, -0.05, 0.08)}};
  std::string body = top_scene(top);
  body.insert(body.find("[[body]]\n") + 9, "Ixy = 0.01\n");
  expect_quadratic_validity([&](double amplitude) {
    return body + "[initial]\ntilt = [[" + num(amplitude) + ", " + num(0.4 * amplitude) + "]]\nrate = [[0.0, " +
           num(2 * amplitude) + "]]\n[run]\nt_end = 1.0\noutput_step = 0.002\n";
  }, "top with I_xy and two tilted tanks off its axis", 5e-3);
}

// A damped 3-D row, as a viscous table holds one (docs/volume.md §7): the closed-form spin-over of a tilted tank made
// synthetic — decay 0.03 and c_left = c̄ + a perturbation, so that H = c c_leftᵀ is of rank one and not Hermitian — to
// exercise the damped terms of both models of the tank (general_system.hpp, volume_fluid.hpp). Not a physical table:
// the checks are of one model against the other.
// Returns the table's name; `Iyz` receives the shell's product that balances the tilted fluid's at density 1000 kg/m³
// and scale 0.1 m (its centroid at O).
std::string damped_tank_table(double& Iyz) {
  rc::ModeTable t = ellipsoid_table(1, 0.8, 0.6, 0.3);
  Iyz = -1000 * std::pow(0.1, 5) * t.volume_cavity.inertia[5];
  Eigen::Matrix3cd H;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H(i, j) = {t.volume_cavity.coupling_re[3 * i + j], t.volume_cavity.coupling_im[3 * i + j]};
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd> es(H);
  const Eigen::Vector3cd c = std::sqrt(es.eigenvalues()[2]) * es.eigenvectors().col(2);
  const Eigen::Vector3cd c_left = c.conjugate() + 0.2 * c.norm() * Eigen::Vector3cd({0.3, {0, -0.5}, 0.2});
  H = c * c_left.transpose();
  const std::complex<double> E = H(0, 0) + H(1, 1), a = std::sqrt(E / 2.0);
  t.ekman = 1e-3;
  t.decay = {0.03};
  t.E = {E.real()};
  t.E_imag = {E.imag()};
  t.a = {a.real()};
  t.a_imag = {a.imag()};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      t.volume_cavity.coupling_re[3 * i + j] = H(i, j).real();
      t.volume_cavity.coupling_im[3 * i + j] = H(i, j).imag();
    }
  write_table(t, test_dir() / "damped_ellipsoid.h5");
  return "damped_ellipsoid.h5";
}

// A hanging top (centre of mass below its fixed point) whose shell has B ≠ A, with the damped tank on its axis
// (viscosity = Ek |spin| L²), released at 0.02 and 0.01 rad: the general chain's exact run against the nonlinear chain,
// the difference falling as the amplitude squared (the synthetic row is not passive, and the top grows slowly, 2.3e-3
// 1/s: the two models must agree whatever the verdict); and the same body free, turned over at large angle by the
// nonlinear chain, keeps its angular momentum J Ω + h (what happens inside the body keeps it, whatever ż's law).
TEST(GeneralChain, NonlinearChainWithADampedTankIsTheGeneralRunAtSmallAmplitude) {
  double Iyz = 0;
  const std::string table = damped_tank_table(Iyz);
  const auto scene_at = [&](double amplitude, bool free_body) {
    return std::string("[system]\nkind = \"") + (free_body ? "free" : "fixed") + "\"\ngravity = " +
           (free_body ? "0.0" : "9.81") + "\n[[body]]\nmass = 3\nA = 0.2\nB = 0.15\nC = 0.12\nIyz = " + num(Iyz) +
           "\ncom = -0.1\nspin = 20\n"
           "[body.cavity]\ntable = \"" + table + "\"\ndensity = 1000\nscale = 0.1\ncenter = 0.0\nviscosity = " +
           num(1e-3 * 20 * 0.01) + "\n[initial]\ntilt = [[" + num(amplitude) + ", " + num(0.4 * amplitude) +
           "]]\nrate = [[0.0, " + num(2 * amplitude) + "]]\n[run]\nt_end = 1.0\noutput_step = 0.002\n";
  };
  double previous = 0;
  for (const double amplitude : {0.02, 0.01}) {
    const Scene scene = parse_scene_text(scene_at(amplitude, false), test_dir(), "t");
    const GeneralChain g = build_general_chain(scene);
    ASSERT_TRUE(g.dissipative);
    const GeneralSpectrum sp = general_spectrum(g);
    const LinearValidity v = linear_validity(scene, propagate_general(g, scene).u);
    ASSERT_TRUE(v.measured) << v.why_not;
    std::printf("hanging top with a damped 3-D tank (%s, slowest decay %.3g 1/s), tilt %g rad: the general run against "
                "the nonlinear chain %.3e of the largest tilt\n", sp.verdict.stable ? "stable" : "unstable",
                -sp.verdict.growth, amplitude, v.difference);
    EXPECT_LT(v.difference, 5e-3);
    if (previous > 0) {
      EXPECT_GT(previous / v.difference, 3.5);  // the amplitude squared: 4
      EXPECT_LT(previous / v.difference, 4.5);
    }
    previous = v.difference;
  }
  std::string free_text = scene_at(0.45, true);
  free_text.replace(free_text.find("[run]\n"), 6, "[run]\nmodel = \"nonlinear\"\ntolerance = 1e-12\n");
  const Scene craft = parse_scene_text(free_text, test_dir(), "t");
  const NonlinearChain chain = nonlinear_chain(craft);
  ASSERT_EQ(chain.bodies[0].volume.size(), 1);
  const NonlinearHistory h = integrate_nonlinear(chain, nonlinear_initial_state(craft, chain), craft.run);
  ASSERT_TRUE(h.momentum_valid);
  std::printf("free body with a damped 3-D tank at 0.45 rad, nonlinear, 1 s, %ld steps: J Omega + h to %.2e\n",
              h.base.integrator_steps, h.max_momentum_drift);
  EXPECT_LT(h.max_momentum_drift, 1e-9);
}

// A free body with the same tanks turned over at large angle by the nonlinear chain keeps its angular momentum with
// the liquid's relative part, J Ω + h: an exact integral of the model (volume_fluid.hpp).
TEST(GeneralChain, NonlinearChainWithTanksKeepsTheAngularMomentum) {
  Top craft;
  craft.g = 0;
  craft.C = 0.4;
  craft.tanks = {Tank{1, 0.8, 0.6, 0.3, Eigen::Vector3d(0.15, 0.05, 0.08)},
                 Tank{1, 0.8, 0.6, 0.3, Eigen::Vector3d(-0.15, -0.05, 0.08)}};
  std::string text = top_scene(craft);
  text.insert(text.find("[[body]]\n") + 9, "Ixy = 0.01\n");
  text.replace(text.find("kind = \"fixed\""), 14, "kind = \"free\"");
  text += "[initial]\ntilt = [[0.4, 0.2]]\nrate = [[1.0, -0.5]]\n[run]\nmodel = \"nonlinear\"\nt_end = 3.0\n"
          "output_step = 0.01\ntolerance = 1e-12\n";
  const Scene scene = parse_scene_text(text, test_dir(), "t");
  const NonlinearChain chain = nonlinear_chain(scene);
  ASSERT_EQ(chain.bodies[0].volume.size(), 2);  // two tanks, one spin-over each (rank one)
  EXPECT_NE(chain.bodies[0].principal_turn, 0.0);
  const NonlinearHistory h = integrate_nonlinear(chain, nonlinear_initial_state(scene, chain), scene.run);
  ASSERT_TRUE(h.momentum_valid);
  double spin_range = 0;
  for (std::size_t j = 0; j < h.spins.size(); ++j) spin_range = std::max(spin_range, std::abs(h.spins[j] - craft.spin));
  std::printf("free body with two tilted tanks off its axis at 0.45 rad, 3 s, %ld steps: angular momentum drift %.2e; "
              "the spin ranges over %.3f rad/s\n", h.base.integrator_steps, h.max_momentum_drift, spin_range);
  EXPECT_LT(h.max_momentum_drift, 1e-9);
  EXPECT_GT(spin_range, 1e-3);
}

// `chain-rom bench` on a scene that needs the general chain (general_bench.hpp): a heavy top with B ≠ A and the
// four-mode table. The reference's two long double methods agree, `exact` in double sits at rounding against it,
// 2-stage Gauss converges at order 4, rk45 reaches 1e-10, and the body roots with 1, 2 and 4 rows kept approach
// those with all of them (the same chain with all kept: to rounding).
TEST(GeneralChain, BenchMeasuresTheGeneralChain) {
  if (!std::filesystem::exists(test_dir() / "four_modes.h5")) write_table(four_mode_table(), test_dir() / "four_modes.h5");
  Body top;
  top.table = "four_modes.h5";
  top.spin = 40;
  top.center = 0.1;
  std::string text = scene_text({top}, {}, 9.81, false, 0.0, "[initial]\ntilt = [[0.01, 0.0]]\n[run]\nt_end = 0.5\n"
                                                            "output_step = 0.01\n");
  text.insert(text.find("\nC = ") + 1, "B = 0.12\n");
  const BenchResult r = run_bench(parse_scene_text(text, test_dir(), "t"));
  double reference = 1, exact = 1, best_rk45 = 1, order = 0;
  std::vector<double> gauss, roots;
  for (const BenchRow& row : r.rows) {
    if (row.method == "reference") reference = row.error;
    if (row.method == "exact") exact = row.error;
    if (row.method == "gauss") gauss.push_back(row.error);
    if (row.method == "rk45") best_rk45 = std::min(best_rk45, row.error);
    if (row.part == "roots") roots.push_back(row.error);
  }
  for (std::size_t i = 1; i < gauss.size(); ++i)  // the asymptotic range: error ratio per halving of h
    if (gauss[i - 1] < 1e-4 && gauss[i] > 1e-10) order = std::log2(gauss[i - 1] / gauss[i]);
  std::printf("general bench (dimension %d): reference eig vs expm %.1e, exact %.1e, gauss order %.2f, rk45 down to "
              "%.1e; body roots with 1, 2, 4 of 4 rows: %.1e %.1e %.1e\n", r.dimension, reference, exact, order,
              best_rk45, roots.size() > 0 ? roots[0] : -1, roots.size() > 1 ? roots[1] : -1,
              roots.size() > 2 ? roots[2] : -1);
  EXPECT_LT(reference, 1e-15);
  EXPECT_LT(exact, 1e-12);
  EXPECT_NEAR(order, 4, 0.2);
  EXPECT_LT(best_rk45, 1e-10);
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_GT(roots[0], 1e3 * roots[2]);
  EXPECT_LT(roots[2], 1e-12);
}

// What the general chain cannot model is refused in one line naming the key; what (26) cannot, too.
TEST(GeneralChain, RefusesWhatItDoesNotModel) {
  const auto refusal = [](const std::string& text, bool general) -> std::string {
    try {
      const Scene scene = parse_scene_text(text, test_dir(), "t");
      if (general) build_general_chain(scene);
      else build_model(scene);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  Top one;
  one.tanks[0].at = Eigen::Vector3d(0.1, 0, 0.05);  // alone off the axis: the centre of mass leaves it
  EXPECT_NE(refusal(top_scene(one), true).find("cavity.offset: the body's centre of mass with its tanks lies off its "
                                               "axis"), std::string::npos) << refusal(top_scene(one), true);
  Top tilted;
  tilted.tanks[0].tilt = 0.5;
  std::string unbalanced = top_scene(tilted);
  unbalanced.replace(unbalanced.find("Iyz = "), 6, "Iyz = 0.0\n# ");  // drop the shell's balance
  EXPECT_NE(refusal(unbalanced, true).find("Ixz: the body with its frozen liquid has products of inertia"),
            std::string::npos) << refusal(unbalanced, true);
  // Two bodies without axial symmetry at different spins: periodic coefficients, taken (Floquet: test_two_spins.cpp);
  // a third spin among them makes them quasi-periodic, refused; an axisymmetric body without tanks at a spin of its
  // own is taken.
  const std::string two_spins = "[system]\nkind = \"fixed\"\ngravity = 9.81\n[[body]]\nmass = 1\nA = 0.1\nB = 0.2\n"
                                "C = 0.3\ncom = 0.1\nnext_joint = 0.3\nspin = 10\n[[body]]\nmass = 1\nA = 0.1\nB = 0.15\n"
                                "C = 0.2\ncom = 0.1\nnext_joint = 0.3\nspin = 11\n[[joint]]\nstiffness = 0.0\n";
  EXPECT_EQ(refusal(two_spins, true), "");
  const std::string three_spins = two_spins + "[[body]]\nmass = 1\nA = 0.1\nB = 0.12\nC = 0.2\ncom = 0.1\nspin = 13\n"
                                              "[[joint]]\nstiffness = 0.0\n";
  EXPECT_NE(refusal(three_spins, true).find("body[3].spin: a third spin among the bodies without axial symmetry"),
            std::string::npos) << refusal(three_spins, true);
  std::string rotor = three_spins;
  rotor.replace(rotor.find("B = 0.12\n"), 9, "");
  EXPECT_EQ(refusal(rotor, true), "");
  Top pair;
  pair.tanks = {Tank{}, Tank{}};
  pair.tanks[0].at = Eigen::Vector3d(0.2, 0, 0);
  pair.tanks[1].at = Eigen::Vector3d(-0.2, 0, 0);
  EXPECT_EQ(refusal(top_scene(pair), true), "");  // balanced: the general chain takes it
  // (26) with an axisymmetric shell (B = A): one tank on the axis only.
  pair.B = one.B = pair.A;
  one.tanks[0].at = Eigen::Vector3d(0.1, 0, 0);  // level with O: no products to balance
  EXPECT_NE(refusal(top_scene(pair), false).find("several tanks on one body"), std::string::npos)
      << refusal(top_scene(pair), false);
  EXPECT_NE(refusal(top_scene(one), false).find("cavity.offset: a tank off the body's axis"), std::string::npos)
      << refusal(top_scene(one), false);
}

}  // namespace
}  // namespace rc::rom::test

namespace rc::rom::test {

TEST(GeneralChain, FreeChainsRigidTurnIsLeftOutOfTheVerdict) {
  // A free chain's rigid turn in space is neutral; in the turning frame it sits at σ = ±spin. With friction the verdict
  // must leave it out, as (26)'s leaves out σ = 0. On the free three-body chain (unstable at every spin tried, as
  // Kelvin–Tait–Chetaev says with friction) the two roots at ±spin are counted neutral and the growth is the largest of
  // the other roots' −Im σ, computed here from the roots; and on a stable set of roots the verdict's slowest decay is
  // the physical one, not the neutral roots' rounding.
  const double spin = 30;
  const GeneralChain g = build_general_chain(parse_scene_text(axisymmetric_chain(true, spin), test_dir(), "test-scene"));
  ASSERT_TRUE(g.dissipative);
  const GeneralSpectrum sp = general_spectrum(g);
  int neutral = 0;
  double slowest = -1e300;
  for (const auto r : sp.roots) {
    if (std::min(std::abs(r - spin), std::abs(r + spin)) <= sp.verdict.tolerance || std::abs(r) <= sp.verdict.tolerance) {
      ++neutral;
      continue;
    }
    slowest = std::max(slowest, -r.imag());
  }
  std::printf("  free chain at %g rad/s: %d neutral roots left out, growth %.6g 1/s (verdict %.6g)\n", spin, neutral,
              slowest, sp.verdict.growth);
  EXPECT_GE(neutral, 2);
  EXPECT_EQ(sp.verdict.at_zero, neutral);
  EXPECT_DOUBLE_EQ(sp.verdict.growth, slowest);
  Eigen::VectorXcd stable(4);
  stable << std::complex<double>(-spin, 3e-16), std::complex<double>(spin, -2e-16), std::complex<double>(-1.5, 5e-3),
      std::complex<double>(1.5, 5e-3);
  const Verdict v = verdict_of_roots(stable, true, spin);
  EXPECT_TRUE(v.stable);
  EXPECT_EQ(v.at_zero, 2);
  EXPECT_DOUBLE_EQ(v.growth, -5e-3);
  EXPECT_GT(verdict_of_roots(stable, true).growth, -1e-15);  // without the spin given: the rounding of ±spin
}

}  // namespace rc::rom::test
