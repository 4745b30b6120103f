#include "separable_cylinder.hpp"

#include "coupling.hpp"
#include "line_space.hpp"
#include "separable_forms.hpp"

#include "eigen_dense.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

namespace rc::modes {
namespace {


// Every eigenpair of one radial problem (header), with its E from the well-conditioned formula
// (coupling.hpp) and the projections s_n, t_n of the coupling functionals on the axial vector.
std::vector<SeparableMode> radial_modes(const RadialForms& f, double mu, double s_n, double t_n, int axial) {
  const int n = static_cast<int>(f.A.rows());
  const Eigen::MatrixXd M = f.A + mu * f.B, K = 4 * mu * f.B;
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(2 * n, 2 * n), Q = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  P.topLeftCorner(n, n) = -2 * f.C;
  P.topRightCorner(n, n) = K;
  P.bottomLeftCorner(n, n) = K;
  Q.topLeftCorner(n, n) = M;
  Q.bottomRightCorner(n, n) = K;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(P, Q, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("separable cylinder: the dense symmetric-definite eigensolver failed (axial vector " +
                             std::to_string(axial) + ")");
  const double nM = M.norm(), nC = f.C.norm(), nB = f.B.norm();
  // The form values of every eigenvector at once (three matrix products instead of matrix-vector products
  // per eigenpair): x = the lower half of z = (λx, x).
  const Eigen::MatrixXd X = solver.eigenvectors().bottomRows(n);
  const Eigen::MatrixXd AX = f.A * X, BX = f.B * X, CX = f.C * X;
  const Eigen::RowVectorXd g1X = f.g1.transpose() * X, g2X = f.g2.transpose() * X;
  std::vector<SeparableMode> modes(2 * n);
  for (int k = 0; k < 2 * n; ++k) {
    const double l = solver.eigenvalues()(k);
    const auto x = X.col(k);
    // Q(λ)x = λ²(A + μB)x + 2λCx − 4μBx
    const Eigen::VectorXd res = l * l * AX.col(k) + (l * l * mu - 4 * mu) * BX.col(k) + 2 * l * CX.col(k);
    SeparableMode& m = modes[k];
    m.lambda = l;
    m.residual = res.norm() / ((l * l * nM + 2 * std::abs(l) * nC + 4 * mu * nB) * x.norm());
    m.axial = axial;
    m.E = coupling_from_forms(l, g1X(k) * s_n, g2X(k) * t_n, x.dot(AX.col(k)), x.dot(CX.col(k)),
                              mu * x.dot(BX.col(k))).E;
  }
  // Radial rank j: eigenvalues come ascending, so the negative ones are ranked from the left, the
  // positive ones from the right. λ = −2 is an exact eigenvalue of every radial problem, with x = r
  // ((Ar − Cr) r = 0, so Q(−2) r = 0) and E = 0: it gets no rank (radial = 0), so that j counts as
  // Stewartson's roots do.
  int neg = 0, null_modes = 0;
  while (neg < 2 * n && modes[neg].lambda < 0) ++neg;
  for (int k = 0; k < neg; ++k) {
    if (modes[k].lambda < -2 + 1e-8) ++null_modes;
    else modes[k].radial = k + 1 - null_modes;
  }
  for (int k = neg; k < 2 * n; ++k) modes[k].radial = 2 * n - k;
  return modes;
}

// Runs body(i) for i in [0, count) on every core; the calling thread reports progress(done, count) after each
// item it finishes (one thread only, so progress needs no lock).
template <class Body>
void parallel_for(int count, Body body, const SeparableProgress& progress) {
  const int workers = std::max(1, std::min<int>(count, static_cast<int>(std::thread::hardware_concurrency())));
  std::atomic<int> next{0}, done{0};
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  auto work = [&](bool reports) {
    for (int i; (i = next++) < count && !failed;) {
      try {
        body(i);
      } catch (...) {
        if (!failed.exchange(true)) failure = std::current_exception();
      }
      const int finished = ++done;
      if (reports && progress) progress(finished, count);
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work, false);
  work(true);
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

// Axial vectors that the coupling functionals do not see carry no E: μ = 0 (constant) and, z′ being measured
// from the mid-plane, the even vectors, whose s_n, t_n come out at 1e-13..1e-12 of the odd ones' from the
// rounding of the axial eigensolver. 1e-9 separates the two with margin; a vector it drops could carry at
// most ~1e-18 of the sum rule, and the sum-rule check (sum_E) would show anything larger.
std::vector<int> coupled_axial_vectors(const Eigen::VectorXd& mu, const Eigen::VectorXd& s, const Eigen::VectorXd& t) {
  const double smax = s.cwiseAbs().maxCoeff(), tmax = t.cwiseAbs().maxCoeff();
  std::vector<int> coupled;
  for (Eigen::Index k = 0; k < mu.size(); ++k)
    if (mu(k) > 0 && (std::abs(s(k)) > 1e-9 * smax || std::abs(t(k)) > 1e-9 * tmax))
      coupled.push_back(static_cast<int>(k));
  return coupled;
}

}  // namespace

SeparableGrid SeparableGrid::graded(double radius, double height, int order, int radial_elements, int axial_elements,
                                    int corner_layers, double inner_radius) {
  SeparableGrid g;
  g.order = order;
  g.inner_radius = inner_radius;
  g.radial = graded_breaks(inner_radius, radius, radial_elements, corner_layers, inner_radius > 0, true);
  g.axial = graded_breaks(-0.5 * height, 0.5 * height, axial_elements, corner_layers, true, true);
  return g;
}

SeparableSpectrum solve_separable_cylinder(double radius, double height, const SeparableGrid& grid,
                                           const SeparableProgress& progress) {
  const double b = grid.inner_radius;
  if (!(radius > 0 && std::isfinite(radius) && height > 0 && std::isfinite(height)))
    throw std::invalid_argument("separable cylinder: radius and height must be positive and finite");
  if (!(b >= 0 && b < radius)) throw std::invalid_argument("separable cylinder: the inner radius must be in [0, radius)");
  const auto spans = [](const std::vector<double>& b, double lo, double hi) {
    return b.size() >= 2 && std::abs(b.front() - lo) <= 1e-12 * (hi - lo) && std::abs(b.back() - hi) <= 1e-12 * (hi - lo);
  };
  if (!spans(grid.radial, b, radius) || !spans(grid.axial, -0.5 * height, 0.5 * height))
    throw std::invalid_argument("separable cylinder: the grid does not span the cylinder");
  // On the axis p = 0 (m = 1); an annulus has no axis, and its inner wall, like the outer one, is a natural
  // condition of the forms (u·n = 0: the boundary terms of Cr at both ends are the wall integral of G_c).
  const LineSpace R(grid.radial, grid.order, b == 0);
  const LineSpace Z(grid.axial, grid.order, false);

  SeparableSpectrum out;
  // Frozen-fluid moments: ∫∫ f(r) g(z) r dr dz factor into 1-D integrals.
  const double r1 = R.integral([](double r) { return r; }), r3 = R.integral([](double r) { return r * r * r; });
  const double z0 = Z.integral([](double) { return 1.0; }), z1 = Z.integral([](double z) { return z; }),
               z2 = Z.integral([](double z) { return z * z; });
  out.fluid = fluid_from_moments(r1 * z0, r1 * z1, r1 * z2, r3 * z0);
  out.radial_dofs = R.ndof();
  out.axial_dofs = Z.ndof();
  out.ndof = static_cast<long>(R.ndof()) * Z.ndof();

  const RadialForms rf = radial_forms(R);
  const AxialForms af = axial_forms(Z, out.fluid.centroid_z);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> axial(af.A, af.B);
  if (axial.info() != Eigen::Success) throw std::runtime_error("separable cylinder: the axial eigensolver failed");
  const Eigen::VectorXd mu = axial.eigenvalues().cwiseMax(0.0);  // μ_0 = 0 (constant) may come out as −1e-15
  const Eigen::VectorXd s = axial.eigenvectors().transpose() * af.s, t = axial.eigenvectors().transpose() * af.t;

  // Zhukovsky: J_zh = π Σ_n b_nᵀ (Ar + μ_n Br)⁻¹ b_n, b_n = g1 s_n − g2 t_n (docs/physics.md §2, Batyr (53)-(56)).
  for (int k = 0; k < Z.ndof(); ++k) {
    const Eigen::VectorXd b = rf.g1 * s(k) - rf.g2 * t(k);
    Eigen::LLT<Eigen::MatrixXd> llt(rf.A + mu(k) * rf.B);
    if (llt.info() != Eigen::Success) throw std::runtime_error("separable cylinder: Zhukovsky factorisation failed");
    out.J_zh += std::numbers::pi * b.dot(llt.solve(b));
  }
  out.sum_rule = out.fluid.A_f - out.J_zh;

  const std::vector<int> coupled = coupled_axial_vectors(mu, s, t);
  out.coupled_axial = static_cast<int>(coupled.size());
  std::vector<std::vector<SeparableMode>> per_axial(coupled.size());
  parallel_for(static_cast<int>(coupled.size()), [&](int i) {
    const int k = coupled[i];
    per_axial[i] = radial_modes(rf, mu(k), s(k), t(k), i);  // n = rank among the coupled vectors
  }, progress);
  for (auto& m : per_axial) out.modes.insert(out.modes.end(), m.begin(), m.end());
  std::sort(out.modes.begin(), out.modes.end(), [](const SeparableMode& a, const SeparableMode& b) { return a.E > b.E; });
  for (const auto& m : out.modes) out.sum_E += m.E;
  return out;
}

}  // namespace rc::modes
