// Galerkin tanks (rom/model/galerkin_fluid.hpp, rom/model/galerkin_energy.hpp; docs/rom.md, "Galerkin tanks"): the kept damped
// modes as a Galerkin basis of the fluid, whose energy H balances the joints' and the fluid's dissipation.
//  * dH/dt from the first-order matrix B at random states (exact for a quadratic H: [H(x + ẋ) − H(x − ẋ)]/2) against
//    −(joint power + fluid dissipation): chains of one spin, fixed and free, with friction, two Galerkin tanks (the
//    cylinder's four damped modes with the static correction, the sphere's spin-over mode), one body without fluid;
//    and with ideal tanks, where H is a second integral beside docs/rom.md's "Energy";
//  * the balance along `run` on its output samples (trapezoidal rule: its error falls as the step squared);
//  * the Galerkin residues: Σ Ẽ real and within the sum rule; an ideal table's Galerkin fluid is its modal one;
//  * what has no such H (spins that differ, modal viscous tanks) says why; bad keys and tables fail on one line.
#include "chain_model.hpp"
#include "closed_form_tables.hpp"
#include "first_order_system.hpp"
#include "galerkin_energy.hpp"
#include "galerkin_fluid.hpp"
#include "mode_table.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

std::string viscous_table(const std::string& name) { return std::string(RC_VISCOUS_TABLES) + "/" + name + ".h5"; }

struct ChainOptions {
  std::string kind = "fixed";
  double spin1 = 100, spin3 = 100;
  double friction = 0.02;
  std::string reduction = "galerkin";
};

// Three bodies on elastic joints, one spin: a cylinder tank (Ek = 1e-3, scale 0.04) in body 1, none in body 2, a
// sphere tank (Ek = 1e-3, scale 0.05) in body 3.
Scene chain_scene(const ChainOptions& o) {
  const double nu1 = 1e-3 * std::abs(o.spin1) * 0.04 * 0.04, nu3 = 1e-3 * std::abs(o.spin3) * 0.05 * 0.05;
  std::ostringstream s;
  s.precision(17);
  s << "[system]\nkind = \"" << o.kind << "\"\ngravity = " << (o.kind == "fixed" ? 9.81 : 0.0) << "\n"
    << "[[body]]\nmass = 3.0\nA = 0.066\nC = 0.05\ncom = 0.12\nnext_joint = 0.30\nspin = " << o.spin1 << "\n"
    << "[body.cavity]\ntable = \"" << viscous_table("cylinder_ek1e-3") << "\"\nviscosity = " << nu1
    << "\ndensity = 1000.0\nscale = 0.04\ncenter = 0.15\nstatic_correction = true\nreduction = \"" << o.reduction
    << "\"\n"
    << "[[body]]\nmass = 2.0\nA = 0.03\nC = 0.01\ncom = 0.10\nnext_joint = 0.25\nspin = " << o.spin1 << "\n"
    << "[[body]]\nmass = 1.0\nA = 0.012\nC = 0.004\ncom = 0.07\nspin = " << o.spin3 << "\n"
    << "[body.cavity]\ntable = \"" << viscous_table("sphere_ek1e-3") << "\"\nviscosity = " << nu3
    << "\ndensity = 1000.0\nscale = 0.05\ncenter = 0.08\nreduction = \"" << o.reduction << "\"\n"
    << "[[joint]]\nstiffness = 200.0\nfriction = " << o.friction << "\n[[joint]]\nstiffness = 100.0\nfriction = "
    << 2 * o.friction << "\n";
  if (o.kind == "fixed") s << "[support]\nfriction = " << 0.5 * o.friction << "\n";
  s << "[initial]\ntilt = [[0.02, 0.0], [0.01, 0.0], [0.0, 0.01]]\nrate = [[0.0, 0.0], [0.0, 0.5], [0.0, 0.0]]\n"
       "[run]\nt_end = 1.0\noutput_step = 0.001\n";
  return parse_scene_text(s.str(), ".", "galerkin-chain");
}

// The largest |dH/dt + joint power + fluid dissipation| over 20 random states x, relative to 2 √(S(x) S(ẋ)), S the
// sum of the absolute values of H's parts (the bound of the bilinear form dH/dt = 2 Re xᴴQẋ by its parts).
double worst_derivative_error(const ChainModel& m) {
  const FirstOrderSystem f = build_first_order(m);
  const GalerkinEnergyMeter meter(m);
  std::mt19937 gen(7);
  std::normal_distribution<double> N(0, 1);
  const auto random = [&](int k) {
    Eigen::VectorXcd x(k);
    for (int i = 0; i < k; ++i) x[i] = cd(N(gen), N(gen));
    return x;
  };
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXcd u = random(m.n) * 0.01, v = random(m.n), z = random(m.n_modes());
    const Eigen::VectorXcd y = f.to_state(m, u, v, z), dy = f.B * y;
    Eigen::VectorXcd du, dv, dw;
    f.from_state(m, dy, du, dv, dw);
    Eigen::VectorXcd dz(m.n_modes());
    for (int l = 0; l < m.n_modes(); ++l) dz[l] = dw[l] - dv[m.modes[l].body];
    // H is a Hermitian quadratic form: [H(x + d) − H(x − d)]/2 = 2 Re xᴴQd = dH/dt along d = ẋ, with no truncation.
    const EnergySample plus = meter(u + du, v + dv, z + dz), minus = meter(u - du, v - dv, z - dz), at = meter(u, v, z);
    const double dH = 0.5 * (plus.energy - minus.energy);
    const double size = 2 * std::sqrt(at.scale * meter(du, dv, dz).scale);
    worst = std::max(worst, std::abs(dH + at.joint_power + at.fluid_dissipation) / size);
  }
  return worst;
}

TEST(GalerkinTanks, EnergyDerivativeIsTheDissipationAtRandomStates) {
  for (const std::string kind : {"fixed", "free"})
    for (const double friction : {0.0, 0.02}) {
      ChainOptions o;
      o.kind = kind;
      o.friction = friction;
      const ChainModel m = build_model(chain_scene(o));
      ASSERT_TRUE(galerkin_energy_unavailable(m).empty()) << galerkin_energy_unavailable(m);
      const double error = worst_derivative_error(m);
      std::printf("  %s chain, joint friction %.2f, %d Galerkin modes: |dH/dt + joint power + fluid dissipation| "
                  "= %.1e of their size\n", kind.c_str(), friction, m.n_modes(), error);
      EXPECT_LT(error, 1e-12);
    }
  // With spin -100 (the flow mirrored: the forms conjugated).
  ChainOptions o;
  o.spin1 = o.spin3 = -100;
  const double error = worst_derivative_error(build_model(chain_scene(o)));
  std::printf("  fixed chain spinning at -100 rad/s: %.1e\n", error);
  EXPECT_LT(error, 1e-12);
}

// The same with an ideal tank (the oblate spheroid's closed-form table): the fluid holds diag(E), dissipates nothing,
// and H is conserved without friction, although docs/rom.md's "Energy" H (weights c_kl with 1/λ_kl) is another
// integral.
TEST(GalerkinTanks, IdealTanksConserveTheSameEnergy) {
  const std::filesystem::path table = std::filesystem::path(RC_ROM_TEST_DIR) / "galerkin_ideal_spheroid.h5";
  rc::write_mode_table(test::spheroid_table(1.0, 0.5), table);
  for (const bool galerkin : {false, true}) {
    std::ostringstream s;
    s << "[system]\nkind = \"fixed\"\ngravity = 9.81\n"
      << "[[body]]\nmass = 3.0\nA = 0.066\nC = 0.02\ncom = 0.12\nnext_joint = 0.30\nspin = 300.0\n"
      << "[body.cavity]\ntable = \"" << table.string()
      << "\"\ndensity = 1000.0\nscale = 0.04\ncenter = 0.15\n" << (galerkin ? "reduction = \"galerkin\"\n" : "")
      << "[[body]]\nmass = 1.0\nA = 0.01\nC = 0.004\ncom = 0.07\nspin = 300.0\n"
      << "[[joint]]\nstiffness = 200.0\n";
    const ChainModel m = build_model(parse_scene_text(s.str(), ".", "ideal-chain"));
    ASSERT_TRUE(galerkin_energy_unavailable(m).empty());
    const double error = worst_derivative_error(m);
    std::printf("  ideal spheroid tank (%s): |dH/dt| = %.1e of its size\n", galerkin ? "galerkin" : "modal", error);
    EXPECT_LT(error, 1e-12);
  }
}

// `run` on one body with the sphere's Galerkin tank, prolate (C < A: the nutation grows) and oblate (it decays): H
// falls by what the fluid dissipates, on the samples to the trapezoidal rule's O(h²).
TEST(GalerkinTanks, RunBalancesTheEnergyOnItsSamples) {
  for (const double C_shell : {0.001, 0.004}) {
    std::vector<double> residual;
    for (const char* step : {"0.001", "0.0005"}) {
      std::ostringstream s;
      s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = " << C_shell
        << "\ncom = 0.0\nspin = 100.0\n[body.cavity]\ntable = \"" << viscous_table("sphere_ek1e-3")
        << "\"\nviscosity = 2.5e-4\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nreduction = \"galerkin\"\n"
        << "[initial]\ntilt = [[0.01, 0.0]]\nrate = [[0.0, 0.5]]\n[run]\nt_end = 2.0\noutput_step = " << step << "\n";
      const Scene scene = parse_scene_text(s.str(), ".", "galerkin-body");
      const History h = propagate(build_model(scene), scene);
      ASSERT_FALSE(h.balance.empty());
      const EnergyBalance& b = h.balance;
      residual.push_back(b.residual);
      std::printf("  C_shell = %.3f, step %s: H %.6e -> %.6e J, fluid dissipated %.6e J, balance residual %.2e\n",
                  C_shell, step, b.energy.front(), b.energy.back(), b.fluid_dissipated, b.residual);
      EXPECT_GT(b.fluid_dissipated, 0);
      EXPECT_LT(b.energy.back(), b.energy.front());
    }
    const double order = std::log2(residual[0] / residual[1]);
    std::printf("  C_shell = %.3f: the balance residual falls at order %.2f\n", C_shell, order);
    EXPECT_NEAR(order, 2, 0.3);
  }
}

// The Galerkin residues of the cylinder's four modes: Σ Ẽ = π f̄ᵀG⁻¹f̄ is real and at most A_f − J_zh; each differs
// from the modal residue by the modes' non-orthogonality. An ideal table's Galerkin fluid is exactly its modal one.
TEST(GalerkinTanks, ResiduesAreTheProjectionsShare) {
  const rc::ModeTable t = rc::read_mode_table(viscous_table("cylinder_ek1e-3"));
  ASSERT_TRUE(t.has_galerkin());
  std::printf("  cylinder table: dissipation mismatch %.1e\n", t.galerkin.dissipation_mismatch);
  EXPECT_LT(t.galerkin.dissipation_mismatch, 1e-8);
  std::vector<int> rows;
  for (int l = 0; l < static_cast<int>(t.size()); ++l) rows.push_back(l);
  const GalerkinFluid g = galerkin_fluid(t, rows);
  const cd sum = g.residue.sum();
  std::printf("  sum of Galerkin residues %.9f%+.1ei, sum rule %.9f\n", sum.real(), sum.imag(), t.sum_rule);
  EXPECT_LT(std::abs(sum.imag()), 1e-12 * sum.real());
  EXPECT_LT(sum.real(), t.sum_rule);
  for (int l = 0; l < static_cast<int>(rows.size()); ++l) {
    const cd modal(t.E[l], t.E_imag[l]);
    std::printf("  row %d: modal E %.6f%+.6fi, Galerkin %.6f%+.6fi\n", l + 1, modal.real(), modal.imag(),
                g.residue[l].real(), g.residue[l].imag());
    EXPECT_LT(std::abs(g.residue[l] - modal), 0.2 * std::abs(modal));
  }
  // 𝔈 1 = conj(Ẽ) (the fluid's momentum is its energy's gradient along the rigid motion).
  EXPECT_LT((g.energy.rowwise().sum() - g.residue.conjugate()).norm(), 1e-12 * g.residue.norm());
}

// A Galerkin response table (cavity-modes response --galerkin): its rows' E are the Galerkin residues already, so the
// modal and the Galerkin reductions give one chain (roots to rounding); it is passive; and with reduction =
// "galerkin" its fluid holds an energy: `run` balances it on the samples (order 2 in the step).
TEST(GalerkinTanks, GalerkinResponseTableIsOneModelWithAnEnergy) {
  const auto scene_with = [](const std::string& reduction, const char* step) {
    std::ostringstream s;
    s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = 0.001\ncom = 0.0\n"
         "spin = 100.0\n[body.cavity]\ntable = \"" << viscous_table("sphere_galerkin_ek1e-3")
      << "\"\nviscosity = 2.5e-4\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nreduction = \"" << reduction
      << "\"\n[initial]\ntilt = [[0.01, 0.0]]\nrate = [[0.0, 0.5]]\n[run]\nt_end = 1.0\noutput_step = " << step << "\n";
    return parse_scene_text(s.str(), ".", "galerkin-response");
  };
  const Spectrum modal = compute_spectrum(build_model(scene_with("modal", "0.001")));
  const Spectrum galerkin = compute_spectrum(build_model(scene_with("galerkin", "0.001")));
  ASSERT_EQ(modal.roots.size(), galerkin.roots.size());
  double worst = 0, radius = 0;
  for (std::size_t k = 0; k < modal.roots.size(); ++k) {
    worst = std::max(worst, std::abs(modal.roots[k].sigma - galerkin.roots[k].sigma));
    radius = std::max(radius, std::abs(modal.roots[k].sigma));
  }
  std::printf("  %zu roots; modal and Galerkin reductions differ by %.1e of the spectral radius; growth %.9f 1/s; "
              "fits not passive: %d\n", modal.roots.size(), worst / radius, galerkin.margin, galerkin.fits_not_passive);
  EXPECT_LT(worst, 1e-9 * radius);
  EXPECT_EQ(galerkin.fits_not_passive, 0);
  std::vector<double> residual;
  for (const char* step : {"0.001", "0.0005"}) {
    const Scene scene = scene_with("galerkin", step);
    const History h = propagate(build_model(scene), scene);
    ASSERT_FALSE(h.balance.empty());
    residual.push_back(h.balance.residual);
    std::printf("  step %s: H %.6e -> %.6e J, fluid dissipated %.6e J, balance residual %.2e\n", step,
                h.balance.energy.front(), h.balance.energy.back(), h.balance.fluid_dissipated, h.balance.residual);
  }
  const double order = std::log2(residual[0] / residual[1]);
  std::printf("  the balance residual falls at order %.2f\n", order);
  EXPECT_NEAR(order, 2, 0.3);
}

TEST(GalerkinTanks, WhatHasNoSuchEnergySaysWhy) {
  ChainOptions o;
  o.spin3 = 120;
  const std::string spins = galerkin_energy_unavailable(build_model(chain_scene(o)));
  EXPECT_NE(spins.find("different rates"), std::string::npos) << spins;
  o = ChainOptions{};
  o.reduction = "modal";
  const std::string modal = galerkin_energy_unavailable(build_model(chain_scene(o)));
  EXPECT_NE(modal.find("modal viscous tank"), std::string::npos) << modal;
  std::printf("  unequal spins: %s\n  modal tanks: %s\n", spins.c_str(), modal.c_str());
}

TEST(GalerkinTanks, BadKeysAndTablesFailOnOneLine) {
  ChainOptions o;
  o.reduction = "both";
  try {
    chain_scene(o);
    ADD_FAILURE() << "reduction = \"both\" accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("reduction"), std::string::npos) << e.what();
  }
  // A damped-mode table without its /galerkin matrices (as tables made before them).
  rc::ModeTable old = rc::read_mode_table(viscous_table("sphere_ek1e-3"));
  old.galerkin = {};
  const std::filesystem::path dir = std::filesystem::path(RC_ROM_TEST_DIR) / "galerkin_old";
  std::filesystem::create_directories(dir);
  rc::write_mode_table(old, dir / "sphere_ek1e-3.h5");
  std::ostringstream s;
  s << "[system]\nkind = \"fixed\"\ngravity = 0.0\n[[body]]\nmass = 0.5\nA = 0.002\nC = 0.004\ncom = 0.0\n"
       "spin = 100.0\n[body.cavity]\ntable = \"" << (dir / "sphere_ek1e-3.h5").string()
    << "\"\nviscosity = 2.5e-4\ndensity = 1000.0\nscale = 0.05\ncenter = 0.0\nreduction = \"galerkin\"\n";
  try {
    build_model(parse_scene_text(s.str(), ".", "old-table"));
    ADD_FAILURE() << "a table without /galerkin accepted";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    std::printf("  %s\n", what.c_str());
    EXPECT_NE(what.find("body[1].cavity.reduction"), std::string::npos);
    EXPECT_NE(what.find("no /galerkin"), std::string::npos);
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace rc::rom

namespace rc::rom {
namespace {

// The Hermitian matrix of a quadratic form q on the first-order states y (polarisation on the unit vectors).
template <class Form>
Eigen::MatrixXcd form_matrix(int dim, const Form& q) {
  Eigen::MatrixXcd P(dim, dim);
  const cd I(0, 1);
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      Eigen::VectorXcd x = Eigen::VectorXcd::Zero(dim), y = x;
      x[j] += 1.0;
      y[i] += 1.0;
      // yᴴPx = ¼ [q(x + y) − q(x − y) + i q(x + iy) − i q(x − iy)]
      P(i, j) = 0.25 * (q(x + y) - q(x - y) + I * q(x + I * y) - I * q(x - I * y));
    }
  return P;
}

// The unique Q with BᴴQ + QB = −P (no two roots with μ_i + conj(μ_j) = 0), by B's eigen-decomposition.
Eigen::MatrixXcd lyapunov(const Eigen::MatrixXcd& B, const Eigen::MatrixXcd& P) {
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(B);
  const Eigen::MatrixXcd& V = es.eigenvectors();
  const Eigen::VectorXcd& mu = es.eigenvalues();
  const Eigen::MatrixXcd Vi = V.inverse();
  Eigen::MatrixXcd X = V.adjoint() * P * V;  // VᴴQV =: Y with conj(μ_i) Y_ij + Y_ij μ_j = −X_ij
  for (int i = 0; i < X.rows(); ++i)
    for (int j = 0; j < X.cols(); ++j) X(i, j) = -X(i, j) / (std::conj(mu[i]) + mu[j]);
  return Vi.adjoint() * X * Vi;
}

// H is the only quadratic form whose rate is −(joint power + fluid dissipation): with damped modes the Lyapunov
// equation has one solution, and for one spin it is H itself. With spins that differ its fluid block is not the
// fluid's energy ½𝔈 — so no energy of that kind exists there, which is why `run` reports none (docs/rom.md).
TEST(GalerkinTanks, EnergyIsTheOnlyFormWithThatDissipation) {
  for (const double spin3 : {100.0, 120.0}) {
    ChainOptions o;
    o.spin3 = spin3;
    o.friction = 0.0;  // the joints' power Re(Wᴴ D u̇) needs one spin for W; the fluid's alone here
    const ChainModel m = build_model(chain_scene(o));
    ChainModel one = m;  // a meter needs one spin: the fluid forms of m with body 3's spin set to body 1's
    for (auto& b : one.bodies) b.omega = m.bodies[0].omega;
    const FirstOrderSystem f = build_first_order(m);
    const GalerkinEnergyMeter meter(one);
    const auto physical = [&](const Eigen::VectorXcd& y) {
      Eigen::VectorXcd u, v, w;
      f.from_state(m, y, u, v, w);
      Eigen::VectorXcd z(m.n_modes());
      for (int l = 0; l < m.n_modes(); ++l) z[l] = w[l] - v[m.modes[l].body];
      return meter(u, v, z);
    };
    const Eigen::MatrixXcd P = form_matrix(f.dim(), [&](const Eigen::VectorXcd& y) { return cd(physical(y).fluid_dissipation); });
    const Eigen::MatrixXcd Q = lyapunov(f.B, P);
    const Eigen::MatrixXcd H = form_matrix(f.dim(), [&](const Eigen::VectorXcd& y) { return cd(physical(y).energy); });
    // The fluid blocks: y's z-part is w = z + u̇, so compare on states with u = u̇ = 0 (the w block).
    const int n = m.n, nm = m.n_modes();
    const double fluid = (Q.bottomRightCorner(nm, nm) - H.bottomRightCorner(nm, nm)).cwiseAbs().maxCoeff() /
                         H.bottomRightCorner(nm, nm).cwiseAbs().maxCoeff();
    const double whole = (Q - H).cwiseAbs().maxCoeff() / H.cwiseAbs().maxCoeff();
    const Eigen::VectorXcd mu = f.B.eigenvalues();
    double gap = 1e300;
    for (int i = 0; i < mu.size(); ++i)
      for (int j = 0; j < mu.size(); ++j) gap = std::min(gap, std::abs(std::conj(mu[i]) + mu[j]));
    const double rQ = (f.B.adjoint() * Q + Q * f.B + P).cwiseAbs().maxCoeff() / P.cwiseAbs().maxCoeff();
    const double rH = (f.B.adjoint() * H + H * f.B + P).cwiseAbs().maxCoeff() / P.cwiseAbs().maxCoeff();
    std::printf("  spins 100, 100, %.0f: the unique form against H: fluid block %.1e, whole %.1e (%d states); "
                "smallest |conj(mu_i) + mu_j| %.1e; residuals Q %.1e, H %.1e\n", spin3, fluid, whole, 2 * n + nm, gap,
                rQ, rH);
    if (spin3 == 100.0) {
      EXPECT_LT(whole, 1e-8);
    } else {
      EXPECT_GT(fluid, 1e-6);  // measured 4.3e-4, against 2e-13 for one spin
    }
  }
}

}  // namespace
}  // namespace rc::rom
