#include "partial_fill_cylinder.hpp"

#include "line_space.hpp"
#include "partial_fill_closed_form.hpp"
#include "separable_forms.hpp"

#include "eigen_dense.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <memory>
#include <string>

namespace rc::modes {

namespace {

// What the radial problems share: the radial forms and the axial vectors' projections.
struct Projections {
  RadialForms radial;
  double b = 0;
  Eigen::VectorXd mu, s, t, w;  // per axial vector: μ, ∫ z′ψ, ∫ ψ′, ∫ ψ (Bz-orthonormal ψ)
};


// The quartic's radial vector x of one eigenvector of the companion form (z = (x, y, λx, λy)), made real: the
// eigenvalue is real, so the eigenvector is real up to a complex phase.
Eigen::VectorXd real_vector(const Eigen::VectorXcd& z, int n) {
  Eigen::Index big = 0;
  z.head(n).cwiseAbs().maxCoeff(&big);
  const std::complex<double> phase = z(big) / std::abs(z(big));
  return (z.head(n) / phase).real();
}

// Every eigenpair of one axial vector's radial quartic (header) with its coupling.
std::vector<PartialFillPair> radial_pairs(const Projections& P, int k) {
  const RadialForms& f = P.radial;
  const double mu = P.mu(k), b = P.b;
  const int n = static_cast<int>(f.A.rows()), m = n + 1;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
  e(0) = 1;  // the dof at r = b (LineSpace numbers the nodes from the left)
  const Eigen::MatrixXd S = e * e.transpose(), M = f.A + mu * f.B + 4 * S;
  Eigen::MatrixXd A2 = Eigen::MatrixXd::Zero(m, m), A1 = Eigen::MatrixXd::Zero(m, m), A0 = Eigen::MatrixXd::Zero(m, m);
  A2.topLeftCorner(n, n) = M;
  A2.block(0, n, n, 1) = -e;
  A2.block(n, 0, 1, n) = -e.transpose();
  A1.topLeftCorner(n, n) = 2 * f.C;
  A0.topLeftCorner(n, n) = -4 * mu * f.B;
  A0(n, n) = 1;
  // Companion form: [0 I; −A2⁻¹A0 −A2⁻¹A1] (x̂, λx̂) = λ (x̂, λx̂).
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A2);
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  L.topRightCorner(m, m).setIdentity();
  L.bottomLeftCorner(m, m) = -lu.solve(A0);
  L.bottomRightCorner(m, m) = -lu.solve(A1);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(L, true);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("partially filled cylinder: the dense eigensolver failed (axial vector " +
                             std::to_string(k) + ")");
  const double nS = 1, nM = M.norm(), nC = f.C.norm(), nB = f.B.norm();
  std::vector<PartialFillPair> out;
  for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i) {
    const std::complex<double> lc = solver.eigenvalues()(i);
    if (std::abs(lc.imag()) > 1e-7 * std::max(1.0, std::abs(lc)))
      throw std::runtime_error("partially filled cylinder: a complex eigenvalue " + std::to_string(lc.real()) + " + " +
                               std::to_string(lc.imag()) + "i (axial vector " + std::to_string(k) + ")");
    const double l = lc.real();
    const Eigen::VectorXd x = real_vector(solver.eigenvectors().col(i), n);
    const Eigen::VectorXd Ax = f.A * x, Bx = f.B * x, Cx = f.C * x;
    const double ex = x(0);
    const Eigen::VectorXd res = -l * l * l * l * ex * e + l * l * (M * x) + 2 * l * Cx - 4 * mu * Bx;
    PartialFillPair p;
    p.lambda = l;
    p.axial = k;
    p.residual = res.norm() / ((l * l * l * l * nS + l * l * nM + 2 * std::abs(l) * nC + 4 * mu * nB) * x.norm());
    FreeSurfaceFormValues v;
    v.f1p = f.g1.dot(x) * P.s(k);
    v.f2p = f.g2.dot(x) * P.t(k);
    v.f3p = b * ex * P.s(k);
    v.g1p = f.g1.dot(x) * P.w(k);
    v.e1p = b * ex * P.w(k);
    v.kh = x.dot(Ax);
    v.gc = x.dot(Cx);
    v.kz = mu * x.dot(Bx);
    v.ss = ex * ex;
    // λ = 0 (only for the z-independent axial vector, μ = 0): steady geostrophic motions, which hold no surface
    // displacement and couple to nothing (docs/physics.md §2); rounding leaves λ ~ 1e-14 there, where the scaled
    // field's 0/0 would give noise.
    if (std::abs(l) > 1e-8) p.coupling = free_surface_coupling(l, v);
    out.push_back(p);
  }
  return out;
}


// Zhukovsky's potential with the free surface at zero potential (the radial dof at r = b left out): for each axial
// vector ∫∫ ∇χ·∇q = ∫∫ (e1 × r_O)·∇q, whose data r + c q is linear in the offset c; J(c) = π Σ (r + cq)ᵀA⁻¹(r + cq).
void zhukovsky_dirichlet(const Projections& P, PartialFillSpectrum& out) {
  const RadialForms& f = P.radial;
  const int n = static_cast<int>(f.A.rows());
  for (Eigen::Index k = 0; k < P.mu.size(); ++k) {
    const Eigen::VectorXd r = (f.g1 * P.s(k) - f.g2 * P.t(k)).tail(n - 1), q = (f.g1 * P.w(k)).tail(n - 1);
    Eigen::LLT<Eigen::MatrixXd> llt((f.A + P.mu(k) * f.B).bottomRightCorner(n - 1, n - 1));
    if (llt.info() != Eigen::Success) throw std::runtime_error("partially filled cylinder: Zhukovsky factorisation failed");
    const Eigen::VectorXd Ar = llt.solve(r);
    out.J_D += std::numbers::pi * r.dot(Ar);
    out.J_D1 += std::numbers::pi * q.dot(Ar);
    out.J_D2 += std::numbers::pi * q.dot(llt.solve(q));
  }
}

}  // namespace

PartialFillSpectrum solve_partially_filled_cylinder(double radius, double height, double fill,
                                                    const SeparableGrid& grid) {
  if (!(radius > 0 && std::isfinite(radius) && height > 0 && std::isfinite(height)))
    throw std::invalid_argument("partially filled cylinder: radius and height must be positive and finite");
  if (!(fill > 0 && fill < 1)) throw std::invalid_argument("partially filled cylinder: the fill must be in (0, 1)");
  const double b = exact::partial_fill_surface_radius(radius, fill);
  const auto spans = [](const std::vector<double>& br, double lo, double hi) {
    return br.size() >= 2 && std::abs(br.front() - lo) <= 1e-12 * (hi - lo) && std::abs(br.back() - hi) <= 1e-12 * (hi - lo);
  };
  if (!spans(grid.radial, b, radius) || !spans(grid.axial, -0.5 * height, 0.5 * height))
    throw std::invalid_argument("partially filled cylinder: the grid does not span the liquid annulus");
  const LineSpace R(grid.radial, grid.order, false);  // no axis: the free surface's condition is natural
  const LineSpace Z(grid.axial, grid.order, false);

  PartialFillSpectrum out;
  out.surface_radius = b;
  const double r1 = R.integral([](double r) { return r; }), r3 = R.integral([](double r) { return r * r * r; });
  const double z0 = Z.integral([](double) { return 1.0; }), z1 = Z.integral([](double z) { return z; }),
               z2 = Z.integral([](double z) { return z * z; });
  out.fluid = fluid_from_moments(r1 * z0, r1 * z1, r1 * z2, r3 * z0);
  const double zc = out.fluid.centroid_z;
  out.K0 = std::numbers::pi * b * b * z0;
  out.K1 = std::numbers::pi * b * b * (z1 - zc * z0);
  out.K2 = std::numbers::pi * b * b * (z2 - 2 * zc * z1 + zc * zc * z0);
  out.radial_dofs = R.ndof();
  out.axial_dofs = Z.ndof();

  out.order = grid.order;
  out.radial_elements = grid.radial_elements();
  out.axial_elements = grid.axial_elements();
  auto P = std::make_unique<Projections>();
  P->radial = radial_forms(R);
  P->b = b;
  const AxialForms af = axial_forms(Z, zc);
  const Eigen::VectorXd w1 = Z.linear([](double, double v, double) { return v; });
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> axial(af.A, af.B);
  if (axial.info() != Eigen::Success) throw std::runtime_error("partially filled cylinder: the axial eigensolver failed");
  P->mu = axial.eigenvalues().cwiseMax(0.0);
  P->s = axial.eigenvectors().transpose() * af.s;
  P->t = axial.eigenvectors().transpose() * af.t;
  P->w = axial.eigenvectors().transpose() * w1;
  zhukovsky_dirichlet(*P, out);
  out.sum_rule = out.fluid.A_f + out.K2 - out.J_D;

  // Every axial vector that U_c or T sees (s, t or w above rounding; the constant one through w only).
  const double smax = P->s.cwiseAbs().maxCoeff(), tmax = P->t.cwiseAbs().maxCoeff(), wmax = P->w.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < P->mu.size(); ++k) {
    if (std::abs(P->s(k)) <= 1e-9 * smax && std::abs(P->t(k)) <= 1e-9 * tmax && std::abs(P->w(k)) <= 1e-9 * wmax)
      continue;
    const auto pairs = radial_pairs(*P, static_cast<int>(k));
    out.pairs.insert(out.pairs.end(), pairs.begin(), pairs.end());
  }
  std::sort(out.pairs.begin(), out.pairs.end(),
            [](const PartialFillPair& x, const PartialFillPair& y) { return x.coupling.E > y.coupling.E; });
  for (const auto& p : out.pairs) out.sum_E += p.coupling.E;
  return out;
}

}  // namespace rc::modes
