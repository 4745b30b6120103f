#include "general_system.hpp"

#include "balancing.hpp"
#include "floquet.hpp"
#include "free_recoil.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rc::rom {

FluidMaps fluid_maps(const GeneralChain& g) {
  const int n = g.n, d = g.dim_q(), m = g.n_modes();
  const double w = g.spin;
  FluidMaps f;
  f.P.setZero(3 * n, d);
  f.R.setZero(3 * n, d);
  f.S.setZero(d, 3 * n);
  f.N.setZero(3 * n, 3 * n);
  f.G.setZero(3 * n, 3 * n);
  Eigen::Matrix2d J;
  J << 0, -1, 1, 0;
  for (int k = 0; k < n; ++k) {
    f.P.block<2, 2>(3 * k, 2 * k) = J;  // the base X (g.base) too: its τ = J Ẋ − ω0 X, as a tilt's δω_t
    if (g.axial && k < g.spinning()) f.P(3 * k + 2, 2 * n + k) = 1;
    f.R.block<2, 2>(3 * k, 2 * k) = -w * Eigen::Matrix2d::Identity();
    f.S.block<2, 2>(2 * k, 3 * k) = w * Eigen::Matrix2d::Identity();
    f.G.block<3, 3>(3 * k, 3 * k) = g.geostrophic[k];
  }
  if (g.base) {  // the base's λ = 0 weight against the bodies' velocities (free_recoil.hpp)
    const int b = 3 * (n - 1);
    f.G.block(b, 0, 3, b) = g.base_geostrophic;
    f.G.block(0, b, b, 3) = g.base_geostrophic.transpose();
  }
  f.N = f.G;
  f.W.setZero(3 * n, 2 * m);
  f.Chat.setZero(2 * m, 3 * n);
  f.Lambda.setZero(2 * m, 2 * m);
  for (int l = 0; l < m; ++l) {
    const GeneralMode& md = g.modes[l];
    // The mode's coupling over its body's velocities and, in the extended free chain, the base's τ (rows 3(n − 1)…).
    const bool on_base = g.base && (md.c_base.squaredNorm() > 0 || md.c_left_base.squaredNorm() > 0);
    const int rows = on_base ? 5 : 3;
    Eigen::VectorXcd c(rows), c_left(rows);
    c.head<3>() = md.c;
    c_left.head<3>() = md.c_left;
    if (on_base) {
      c.tail<2>() = md.c_base;
      c_left.tail<2>() = md.c_left_base;
    }
    const auto at = [&](int i) { return i < 3 ? 3 * md.body + i : 3 * (n - 1) + i - 3; };
    for (int i = 0; i < rows; ++i) {
      // W Ĉ = 2 Re(c c_leftᵀ): the mode's share of the fluid that does not follow the body (ideal: 2 Re(c cᴴ)).
      for (int j = 0; j < rows; ++j) f.N(at(i), at(j)) += 2 * (c[i] * c_left[j]).real();
      f.W(at(i), 2 * l) = 2 * c[i].real();
      f.W(at(i), 2 * l + 1) = -2 * c[i].imag();
      f.Chat(2 * l, at(i)) = c_left[i].real();
      f.Chat(2 * l + 1, at(i)) = c_left[i].imag();
    }
    // iλ z with λ = λ_r + i·decay: (Re, Im) ↦ (−λ_r Im − decay Re, λ_r Re − decay Im).
    f.Lambda(2 * l, 2 * l) = f.Lambda(2 * l + 1, 2 * l + 1) = -md.lambda.imag();
    f.Lambda(2 * l, 2 * l + 1) = -md.lambda.real();
    f.Lambda(2 * l + 1, 2 * l) = md.lambda.real();
  }
  return f;
}

Eigen::MatrixXd effective_inertia(const GeneralChain& g) {
  const FluidMaps f = fluid_maps(g);
  return g.M - f.P.transpose() * f.N * f.P;
}

void check_effective_inertia(const Scene& scene, const GeneralChain& g) {
  // A viscous mode's share 2 Re(c c_leftᵀ) is not symmetric: its symmetric part positive definite keeps the whole
  // invertible (xᵀ M x > 0 for every real x ≠ 0), and for the ideal fluid it is the matrix itself.
  const Eigen::MatrixXd Meff = effective_inertia(g);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Meff + Meff.transpose()), Eigen::EigenvaluesOnly);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(g.M, Eigen::EigenvaluesOnly);
  const double lo = es.eigenvalues().minCoeff(), hi = em.eigenvalues().cwiseAbs().maxCoeff();
  if (!(lo > 1e-13 * std::max(hi, 1e-300))) {
    std::ostringstream os;
    os << "the effective inertia (the bodies with their frozen fluid, less what its modes take) is not positive "
          "definite (smallest eigenvalue " << lo << " kg m^2): a shell's moments and products that no body has, or a "
          "shell that carries no inertia beyond what the fluid modes take";
    throw SceneError(scene.file.string() + ": body: " + os.str());
  }
}

GeneralSystem build_general_system(const GeneralChain& g, double s) {
  if (g.recoil) return reduce_on_recoil(g, *g.recoil, build_general_system(*g.recoil, s));
  if (g.periodic())
    throw std::runtime_error("the chain's coefficients are periodic (a body without axial symmetry or with tanks turns "
                             "against another): spectrum, sweep, run, bench and response take it, confirm takes "
                             "chains whose coefficients are constant (docs/rom.md, \"Bodies at different spins\")");
  const FluidMaps f = fluid_maps(g);
  const int nq = 2 * g.n, d = g.dim_q(), nz = 2 * g.n_modes();
  const Eigen::MatrixXd Pt = f.P.transpose();
  const Eigen::MatrixXd Meff = g.M - Pt * f.N * f.P;
  const Eigen::MatrixXd Ceff = g.C - Pt * f.N * f.R - f.S * f.G * f.P;
  const Eigen::MatrixXd Keff = (g.K - f.S * f.G * f.R).leftCols(nq);  // the angles ψ never enter
  const Eigen::MatrixXd Bz = Pt * f.W * f.Lambda + f.S * f.W;
  const Eigen::PartialPivLU<Eigen::MatrixXd> Minv(Meff);  // not symmetric with a viscous mode's share
  const Eigen::MatrixXd Xq = -Minv.solve(Keff), Xv = -Minv.solve(Ceff), Xz = -Minv.solve(Bz);
  GeneralSystem sys;
  const double stiff = (Xq.rows() > 0) ? Xq.norm() : 0.0;
  sys.s = s > 0 ? s : stiff > 0 ? std::sqrt(stiff) : std::max(std::abs(g.spin), 1.0);
  sys.B.setZero(nq + d + nz, nq + d + nz);
  sys.B.block(0, nq, nq, nq) = sys.s * Eigen::MatrixXd::Identity(nq, nq);
  sys.B.block(nq, 0, d, nq) = Xq / sys.s;
  sys.B.block(nq, nq, d, d) = Xv;
  sys.B.block(nq, nq + d, d, nz) = Xz;
  const Eigen::MatrixXd CP = f.Chat * f.P;
  sys.B.block(nq + d, 0, nz, nq) = -CP * Xq / sys.s;
  sys.B.block(nq + d, nq, nz, d) = -CP * Xv - f.Chat * f.R;
  sys.B.block(nq + d, nq + d, nz, nz) = f.Lambda - CP * Xz;
  // A force F on Q adds M_eff⁻¹F to Q̈, and so −Ĉ P M_eff⁻¹F to Ż.
  const Eigen::MatrixXd Xf = Minv.solve(Eigen::MatrixXd::Identity(d, d));
  sys.input.setZero(nq + d + nz, d);
  sys.input.block(nq, 0, d, d) = Xf;
  sys.input.block(nq + d, 0, nz, d) = -CP * Xf;
  // Values each in range can overflow together (an eigen-solver given a NaN may never return: fuzz, docs/rom.md
  // "Limits"): refused before any solver sees them.
  if (!sys.B.allFinite())
    throw std::runtime_error("the chain's first-order matrix overflows double precision (masses, inertias, lengths, "
                             "spins or gravity too large together)");
  return sys;
}

GeneralSpectrum general_spectrum(const GeneralChain& g) {
  if (g.periodic()) return floquet_spectrum(g);
  GeneralSystem sys = build_general_system(g);
  GeneralSpectrum sp;
  sp.recoil_residual = sys.recoil_residual;
  balance_in_place(sys.B);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(sys.B, false);
  if (es.info() != Eigen::Success)
    throw std::runtime_error("the general chain's eigen-solver did not converge (" + std::to_string(sys.dim()) +
                             " states)");
  Eigen::VectorXcd sigma(es.eigenvalues().size());
  for (Eigen::Index i = 0; i < sigma.size(); ++i) {
    const std::complex<double> mu = es.eigenvalues()[i];
    sigma[i] = {mu.imag(), -mu.real()};  // σ = −iμ
    sp.roots.push_back(sigma[i]);
  }
  std::sort(sp.roots.begin(), sp.roots.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  sp.verdict = verdict_of_roots(sigma, g.dissipative, std::abs(g.spin));
  return sp;
}

}  // namespace rc::rom
