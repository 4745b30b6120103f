// The sphere and the spherical shell by spectral expansion (docs/spherical.md): the ultraspherical operators exact on
// polynomials, the Stokes limit (strong viscosity: spherical Bessel zeros), Kore's own test case and values, and our
// finite elements.
#include "cavity_table.hpp"
#include "shell_modes.hpp"
#include "shell_response.hpp"
#include "shell_table.hpp"
#include "ultraspherical.hpp"
#include "viscous_response.hpp"
#include "viscous_table.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

using namespace rc::modes;
using namespace rc::modes::spherical;
using cd = std::complex<double>;
using rc::ModeTable;

namespace {

// Σ a_k C^(λ)_k(x) by the three-term recurrence (DLMF 18.9.1); λ = 0: the Chebyshev T_k(x) = cos(k arccos x).
double evaluate(const Eigen::VectorXd& a, int lambda, double x) {
  double sum = 0, previous = 0, current = 1;
  for (int k = 0; k < a.size(); ++k) {
    sum += a[k] * (lambda == 0 ? std::cos(k * std::acos(x)) : current);
    const double next = (2 * (k + lambda) * x * current - (k + 2 * lambda - 1) * previous) / (k + 1);
    previous = current;
    current = next;
  }
  return sum;
}

// The derivative's Chebyshev coefficients by the classical backward recurrence b_{k−1} = b_{k+1} + 2k a_k (b_0 halved).
Eigen::VectorXd chebyshev_derivative(const Eigen::VectorXd& a) {
  const int n = static_cast<int>(a.size());
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 1);
  for (int k = n - 1; k >= 1; --k) b[k - 1] = b[k + 1] + 2 * k * a[k];
  b[0] /= 2;
  return b.head(n);
}

// ShellSettings for a run at the default truncation times `factor`.
ShellSettings settings(double ri, double ekman, bool toroidal_first = true, double factor = 1.0) {
  ShellSettings s;
  s.inner_radius = ri;
  s.ekman = ekman;
  s.toroidal_first = toroidal_first;
  const Truncation t = default_truncation(ekman, ri, 1, factor);
  s.radial = t.radial;
  s.lmax = t.lmax;
  return s;
}

ViscousMode nearest(const ShellSettings& s, cd target) {
  const auto t0 = std::chrono::steady_clock::now();
  const ViscousMode m = shell_modes_near(s, target, 1, PETSC_COMM_WORLD).front();
  std::printf("  %s r_i = %g, Ek = %g, %d x %d: lambda %.15f + %.15f i, backward error %.1e, %.2f s\n",
              s.inner_radius > 0 ? "shell" : "sphere", s.inner_radius, s.ekman, s.radial, s.lmax, m.lambda.real(),
              m.lambda.imag(), m.residual,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return m;
}

// Kore's values, data/reference/kore_{shell,sphere}_spinover.csv: Ek → (λ, decay).
std::map<std::string, cd> kore_values(const std::string& shape) {
  std::ifstream in(std::string(RC_REFERENCE_DIR) + "/kore_" + shape + "_spinover.csv");
  std::map<std::string, cd> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("ekman", 0) == 0) continue;
    std::stringstream row(line);
    std::string ek, lambda, decay;
    std::getline(row, ek, ',');
    std::getline(row, lambda, ',');
    std::getline(row, decay, ',');
    out[ek] = {std::stod(lambda), std::stod(decay)};
  }
  return out;
}

double relative(double x, double reference) { return std::abs(x - reference) / std::abs(reference); }

}  // namespace

// Each operator against an independent evaluation at points of [-1, 1], on a random polynomial of degree 29 kept in
// 40 coefficients (so nothing is cut).
TEST(Ultraspherical, OperatorsAreExactOnPolynomials) {
  const int n = 40;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 30; ++k) a[k] = uniform(random);
  double worst = 0;
  Eigen::VectorXd d = a;
  for (int k = 1; k <= 4; ++k) {
    d = chebyshev_derivative(d);  // the k-th derivative in Chebyshev T
    const Eigen::VectorXd ours = derivative(n, k) * a;  // … in C^(k)
    for (double x : {-0.97, -0.3, 0.1, 0.55, 0.99}) worst = std::max(worst, std::abs(evaluate(ours, k, x) - evaluate(d, 0, x)) / (1 + std::abs(evaluate(d, 0, x))));
  }
  for (int lambda = 0; lambda <= 3; ++lambda) {
    const Eigen::VectorXd up = conversion(n, lambda) * a, times_r = multiply_by_r(n, lambda, 0.3, 0.6, 3) * a;
    for (double x : {-0.97, -0.3, 0.1, 0.55, 0.99}) {
      worst = std::max(worst, std::abs(evaluate(up, lambda + 1, x) - evaluate(a, lambda, x)));
      worst = std::max(worst, std::abs(evaluate(times_r, lambda, x) - std::pow(0.3 * x + 0.6, 3) * evaluate(a, lambda, x)));
    }
  }
  std::printf("derivatives (orders 1-4), conversions (C^(0..3) up one) and r^3 products: worst error %.1e\n", worst);
  EXPECT_LE(worst, 1e-10);
}

// Strong viscosity (Ek = 1e4): the Coriolis terms are a 1/Ek perturbation, so the slowest decays are Ek k² with k the
// Stokes operator's closed-form roots. Toroidal l = 1 (the spin-over's symmetry): j_1(k) = 0, k = 4.4934094579, and
// the frequency tends to 2m/L = 1; poloidal l = 1 (no-slip, P = P′ = 0 at r = 1): j_2(k) = 0, k = 5.7634591969 — the
// root of the toroidal l = 2 as well, so the Coriolis coupling splits that pair's frequencies at order one (1.51
// measured) and only the decay is checked; the shell's toroidal l = 1: j_1(k) y_1(k r_i) = j_1(k r_i) y_1(k).
TEST(SphericalShell, StokesLimitIsTheBesselRoots) {
  const double ek = 1e4;
  auto root = [](auto f, double lo, double hi) {
    for (int i = 0; i < 200; ++i) {
      const double mid = (lo + hi) / 2;
      (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
    }
    return (lo + hi) / 2;
  };
  const double ri = 0.35;
  const double k_toroidal = root([](double k) { return std::sph_bessel(1, k); }, 4, 5);
  const double k_poloidal = root([](double k) { return std::sph_bessel(2, k); }, 5, 6.5);
  const double k_shell = root([&](double k) {
    return std::sph_bessel(1, k) * std::sph_neumann(1, k * ri) - std::sph_bessel(1, k * ri) * std::sph_neumann(1, k);
  }, 4, 5.5);
  struct Case { double ri; bool toroidal_first; double k; const char* what; bool frequency = true; };
  for (const Case& c : {Case{0, true, k_toroidal, "sphere, toroidal l = 1"},
                        Case{0, false, k_poloidal, "sphere, poloidal l = 1 (and toroidal l = 2)", false},
                        Case{ri, true, k_shell, "shell, toroidal l = 1"}}) {
    ShellSettings s = settings(c.ri, ek, c.toroidal_first);
    const double decay = ek * c.k * c.k;
    const ViscousMode m = nearest(s, cd(1.0, 1.01 * decay));  // a target on the mode itself is a singular shift
    std::printf("%s: decay/Ek %.12f against k^2 = %.12f (%.1e), frequency %.8f\n", c.what, m.lambda.imag() / ek,
                c.k * c.k, relative(m.lambda.imag(), decay), m.lambda.real());
    EXPECT_LE(relative(m.lambda.imag(), decay), 1e-7) << c.what;
    if (c.frequency) {
      EXPECT_NEAR(m.lambda.real(), 1.0, 1e-3) << c.what;
    }
  }
}

// Kore's own test (tests/spinover: the shell r_i = 0.35, both walls no-slip, Ek = 1e-3) to its reference eigenvalue,
// and Kore's runs at Ek = 1e-4 (the shell) and 1e-5 (the full sphere), each converged to 1e-13 … 1e-10 by Kore's own
// finer runs (data/reference/kore_*_spinover.csv). The shell at 1e-4 also at twice the truncation: there MUMPS's
// default pivoting lost the mode while each block's wall rows came last (docs/spherical.md §3).
TEST(SphericalShell, SpinOverModeIsKoresAndConverges) {
  const auto shell = kore_values("shell"), sphere = kore_values("sphere");
  ASSERT_EQ(shell.count("1e-3") + shell.count("1e-4") + sphere.count("1e-5"), 3u);
  struct Case { double ri, ek; cd kore; double tolerance, factor = 1.0; };
  for (const Case& c : {Case{0.35, 1e-3, shell.at("1e-3"), 1e-12}, Case{0.35, 1e-4, shell.at("1e-4"), 1e-11},
                        Case{0.35, 1e-4, shell.at("1e-4"), 1e-11, 2.0}, Case{0, 1e-5, sphere.at("1e-5"), 1e-9}}) {
    const cd target(1.0, 2.6 * std::sqrt(c.ek));  // the command's: the Ekman layer's decay (shell_command.cpp)
    const ViscousMode m = nearest(settings(c.ri, c.ek, true, c.factor), target);
    const ViscousMode coarse = nearest(settings(c.ri, c.ek, true, 0.8 * c.factor), target);
    const double frequency = relative(m.lambda.real(), c.kore.real()), decay = relative(m.lambda.imag(), c.kore.imag());
    std::printf("r_i = %g, Ek = %g, %g times the truncation: against Kore: frequency %.1e, decay %.1e; against 0.8 "
                "times it %.1e\n", c.ri, c.ek, c.factor, frequency, decay,
                std::abs(m.lambda - coarse.lambda) / std::abs(m.lambda.imag()));
    EXPECT_LE(frequency, c.tolerance);
    EXPECT_LE(decay, c.tolerance);
    EXPECT_LE(m.residual, 1e-12);
  }
}

// The full sphere at Ek = 1e-3 against our finite elements (the meridian Taylor–Hood solver, docs/viscous.md):
// two discretisations sharing no code but the eigensolver.
TEST(SphericalShell, SphereIsTheFiniteElementsMode) {
  TableRequest ideal;
  ideal.shape = {"sphere", {{"radius", 1.0}}, {}};
  ideal.mesh.order = 6;
  ideal.selection.modes = 1;
  ideal.check_convergence = false;
  ViscousTableSettings v;
  v.ekman = 1e-3;
  v.mesh.order = 0;
  v.check_convergence = false;
  const ModeTable fe = compute_viscous_table(ideal.shape, v, compute_mode_table(ideal), {});
  const ViscousMode m = nearest(settings(0, 1e-3), cd(1.0, 2.6 * std::sqrt(1e-3)));
  std::printf("finite elements (%ld unknowns): %.12f + %.12f i; spectral: frequency %.1e, decay %.1e apart\n",
              fe.ndof, fe.lambda[0], fe.decay[0], relative(fe.lambda[0], m.lambda.real()),
              relative(fe.decay[0], m.lambda.imag()));
  EXPECT_LE(relative(fe.lambda[0], m.lambda.real()), 1e-8);
  EXPECT_LE(relative(fe.decay[0], m.lambda.imag()), 3e-7);  // 1.2e-7 measured: the finite elements' own error
}

TEST(SphericalShell, SettingsThatDescribeNoProblemAreRefused) {
  ShellSettings s = settings(0.35, 1e-3);
  for (auto change : std::vector<std::function<void(ShellSettings&)>>{
           [](ShellSettings& x) { x.ekman = 0; }, [](ShellSettings& x) { x.inner_radius = 1; },
           [](ShellSettings& x) { x.inner_radius = -0.1; }, [](ShellSettings& x) { x.radial = 4; },
           [](ShellSettings& x) { x.lmax = 1; }, [](ShellSettings& x) { x.m = -1; }}) {
    ShellSettings bad = s;
    change(bad);
    EXPECT_THROW(assemble_shell_pencil(bad), std::invalid_argument);
  }
}

namespace {

// The finite elements' R(σ) (the meridian Taylor–Hood forced solves, docs/viscous.md §6) of a cavity at order 6 on
// its default viscous mesh.
std::vector<cd> finite_element_response(const rc::geometry::ShapeSpec& shape, double ek, const std::vector<cd>& sigma) {
  rc::geometry::MeshOptions m;
  m.order = 6;
  return cavity_response(shape, viscous_mesh_defaults(shape, ek, m), ek, sigma);
}

double largest_relative_gap(const std::vector<cd>& a, const std::vector<cd>& b) {
  double worst = 0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]) / std::abs(b[k]));
  return worst;
}

}  // namespace

// The spectral forced response of the full sphere against the finite elements' at Ek = 1e-3: two discretisations
// sharing no code but MUMPS, at frequencies on both sides, near the spin-over pole and off the real axis.
TEST(SphericalShell, SphereResponseIsTheFiniteElementsResponse) {
  const std::vector<cd> sigma{0.5, cd(1.02, 0.01), cd(-0.7, 0.3), 1.5, -2.5, cd(0.2, -0.05)};
  ShellResponse spectral(settings(0, 1e-3), PETSC_COMM_WORLD);
  std::vector<cd> R;
  for (const cd s : sigma) R.push_back(spectral(s));
  const std::vector<cd> fe = finite_element_response({"sphere", {{"radius", 1.0}}, {}}, 1e-3, sigma);
  for (std::size_t k = 0; k < sigma.size(); ++k)
    std::printf("sigma %+.2f%+.2fi: spectral %.12f%+.12fi, finite elements %.1e apart\n", sigma[k].real(),
                sigma[k].imag(), R[k].real(), R[k].imag(), std::abs(R[k] - fe[k]) / std::abs(R[k]));
  EXPECT_LE(largest_relative_gap(fe, R), 1e-6);
}

// The spherical shell of Kore's test case (r_i = 0.35) against the finite elements on its section file.
TEST(SphericalShell, ShellResponseIsTheFiniteElementsResponse) {
  const std::vector<cd> sigma{0.5, cd(1.02, 0.01), -1.2, cd(0.3, 0.2)};
  ShellResponse spectral(settings(0.35, 1e-3), PETSC_COMM_WORLD);
  std::vector<cd> R;
  for (const cd s : sigma) R.push_back(spectral(s));
  const rc::geometry::ShapeSpec shell{"section", {}, std::string(RC_SECTIONS_DIR) + "/shell.geo"};
  const std::vector<cd> fe = finite_element_response(shell, 1e-3, sigma);
  for (std::size_t k = 0; k < sigma.size(); ++k)
    std::printf("sigma %+.2f%+.2fi: spectral %.12f%+.12fi, finite elements %.1e apart\n", sigma[k].real(),
                sigma[k].imag(), R[k].real(), R[k].imag(), std::abs(R[k] - fe[k]) / std::abs(R[k]));
  EXPECT_LE(largest_relative_gap(fe, R), 1e-6);
}

// Strong viscosity (Kononov 1999 after (18), from Chernousko 1968): the sphere's R(0) = i (8π/525)/Ek + O(Ek⁻²)
// (docs/viscous.md, "Strong viscosity"), a closed form: the relative gap must fall as 1/Ek.
TEST(SphericalShell, SphereResponseAtStrongViscosityIsTheStokesLimit) {
  const double P1 = 8 * std::numbers::pi / 525;
  std::vector<double> gap;
  for (const double ek : {1e2, 1e3}) {
    ShellResponse R(settings(0, ek), PETSC_COMM_WORLD);
    const cd scaled = R(0.0) * ek / cd(0, 1);
    gap.push_back(std::abs(scaled - P1) / P1);
    std::printf("Ek %.0e: R(0) Ek / i = %.12f%+.3ei against 8 pi/525 = %.12f: %.2e\n", ek, scaled.real(), scaled.imag(),
                P1, gap.back());
  }
  EXPECT_LE(gap[1], 2e-3);
  EXPECT_LE(gap[1], 0.2 * gap[0]);  // O(1/Ek): ten times smaller per decade, within a margin
}

// A response table by the spectral solves: its pseudo-modes' R against spectral forced solves at frequencies it was
// not fitted on (within its error), its residues' sum against A_f (the sum rule, to the fit's reach), and the
// heaviest pole against the spin-over mode of the eigensolver on the same pencil.
TEST(SphericalShell, ResponseTableIsTheSpectralResponse) {
  ShellTableRequest req{settings(0, 1e-3), settings(0, 1e-3, true, 0.8), {}, 1e-7};
  for (int k = 0; k <= 40; ++k) req.window.push_back(-1.5 + 3.5 * k / 40);
  const ShellTable made = shell_response_table(req, [](const std::string&) {});
  const ModeTable& t = made.table;
  ShellResponse R(req.fine, PETSC_COMM_WORLD);
  double worst = 0, scale = 0;
  for (const double s : {-1.33, -0.41, 0.123, 0.97, 1.05, 1.77}) {
    cd fit = 0;
    for (std::size_t j = 0; j < t.lambda.size(); ++j) fit += cd(t.E[j], t.E_imag[j]) / (s - cd(t.lambda[j], t.decay[j]));
    const cd exact = R(s);
    worst = std::max(worst, std::abs(fit - exact));
    scale = std::max(scale, std::abs(exact));
  }
  const auto heaviest = std::max_element(t.E.begin(), t.E.end()) - t.E.begin();
  const ViscousMode mode = nearest(req.fine, cd(1.0, 2.6 * std::sqrt(1e-3)));
  std::printf("%zu pseudo-modes, fit error %.1e, truncation change %.1e; R from the rows against forced solves %.1e of "
              "max|R|; heaviest pole %.10f%+.10fi, the eigensolver's %.1e off\n", t.lambda.size(), t.fit_error,
              made.truncation_change, worst / scale, t.lambda[heaviest], t.decay[heaviest],
              std::abs(cd(t.lambda[heaviest], t.decay[heaviest]) - mode.lambda));
  EXPECT_LE(worst / scale, 10 * t.fit_error);
  EXPECT_LE(made.truncation_change, 1e-8);
  EXPECT_LE(std::abs(cd(t.lambda[heaviest], t.decay[heaviest]) - mode.lambda), 1e-6);
  EXPECT_EQ(t.shape, "sphere");
  EXPECT_NEAR(t.A_f, 8 * std::numbers::pi / 15, 1e-15);
}
