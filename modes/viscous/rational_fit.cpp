#include "rational_fit.hpp"

#include "complex_svd.hpp"
#include "eigen_dense.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

using C = std::complex<double>;
using VecC = Eigen::VectorXcd;
using MatC = Eigen::MatrixXcd;

struct Barycentric {
  VecC support, values, weights;  // z_j, f_j, w_j:  r(s) = Σ w_j f_j/(s − z_j) / Σ w_j/(s − z_j)
};

// The AAA iteration (Nakatsukasa, Sète, Trefethen 2018, Fig. 4.1): greedy support points where the current
// approximant errs most, weights from the smallest right singular vector of the Loewner matrix on the rest.
Barycentric aaa(const VecC& Z, const VecC& F, double tolerance, int max_degree) {
  const Eigen::Index M = Z.size();
  const double scale = F.cwiseAbs().maxCoeff();
  std::vector<bool> is_support(static_cast<std::size_t>(M), false);
  std::vector<Eigen::Index> picked;
  VecC R = VecC::Constant(M, F.mean());
  Barycentric b;
  for (int m = 1; m <= std::min<Eigen::Index>(max_degree, M / 2); ++m) {
    Eigen::Index j = 0;
    (F - R).cwiseAbs().maxCoeff(&j);
    is_support[static_cast<std::size_t>(j)] = true;
    picked.push_back(j);
    std::vector<Eigen::Index> rest;
    for (Eigen::Index i = 0; i < M; ++i)
      if (!is_support[static_cast<std::size_t>(i)]) rest.push_back(i);
    const auto n = static_cast<Eigen::Index>(picked.size());
    MatC cauchy(static_cast<Eigen::Index>(rest.size()), n), loewner(cauchy.rows(), n);
    for (Eigen::Index r = 0; r < cauchy.rows(); ++r)
      for (Eigen::Index c = 0; c < n; ++c) {
        cauchy(r, c) = 1.0 / (Z[rest[r]] - Z[picked[c]]);
        loewner(r, c) = (F[rest[r]] - F[picked[c]]) * cauchy(r, c);
      }
    b.support.resize(n);
    b.values.resize(n);
    for (Eigen::Index c = 0; c < n; ++c) {
      b.support[c] = Z[picked[c]];
      b.values[c] = F[picked[c]];
    }
    b.weights = smallest_right_singular_vector(loewner, "the AAA fit's Loewner matrix");
    R = F;
    const VecC num = cauchy * b.weights.cwiseProduct(b.values), den = cauchy * b.weights;
    for (Eigen::Index r = 0; r < cauchy.rows(); ++r) R[rest[r]] = num[r] / den[r];
    if ((F - R).cwiseAbs().maxCoeff() <= tolerance * scale) break;
  }
  return b;
}

// The zeros of Σ w_j/(s − z_j): the finite eigenvalues of the arrowhead pencil (E, B), E = [[0, wᵀ], [1, diag z]],
// B = diag(0, 1, …, 1), found as s = s0 + 1/μ from the eigenvalues μ ≠ 0 of (E − s0 B)⁻¹ B.
std::vector<C> barycentric_poles(const Barycentric& b) {
  const Eigen::Index n = b.support.size();
  MatC E = MatC::Zero(n + 1, n + 1), B = MatC::Identity(n + 1, n + 1);
  B(0, 0) = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    E(0, j + 1) = b.weights[j];
    E(j + 1, 0) = 1.0;
    E(j + 1, j + 1) = b.support[j];
  }
  // A shift off the real axis, where no support point lies, away from the poles of a passive response (Im > 0).
  const C s0(b.support.real().mean(), -1.0 - b.support.real().cwiseAbs().maxCoeff());
  const MatC K = (E - s0 * B).partialPivLu().solve(B);
  Eigen::ComplexEigenSolver<MatC> eig(K, false);
  if (eig.info() != Eigen::Success) throw std::runtime_error("AAA: the pole eigenproblem did not converge");
  const double mu_max = eig.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<C> poles;
  for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i) {
    const C mu = eig.eigenvalues()[i];
    if (std::abs(mu) > 1e-13 * mu_max) poles.push_back(s0 + 1.0 / mu);
  }
  return poles;
}

// Least-squares residues of Σ r_j/(s − p_j) on the samples; returns the residues.
VecC residues_for(const VecC& Z, const VecC& F, const std::vector<C>& poles) {
  MatC A(Z.size(), static_cast<Eigen::Index>(poles.size()));
  for (Eigen::Index i = 0; i < Z.size(); ++i)
    for (std::size_t j = 0; j < poles.size(); ++j) A(i, static_cast<Eigen::Index>(j)) = 1.0 / (Z[i] - poles[j]);
  return A.colPivHouseholderQr().solve(F);
}

// Largest |r/(z − p)| over the samples: what the pole contributes on the real axis.
double contribution(const VecC& Z, C p, C r) {
  double worst = 0;
  for (Eigen::Index i = 0; i < Z.size(); ++i) worst = std::max(worst, std::abs(r / (Z[i] - p)));
  return worst;
}

}  // namespace

C RationalFit::operator()(C s) const {
  C sum = 0;
  for (std::size_t j = 0; j < poles.size(); ++j) sum += residues[j] / (s - poles[j]);
  return sum;
}

RationalFit fit_response(const std::vector<double>& z, const std::vector<C>& f, double tolerance, int max_degree) {
  if (z.size() != f.size() || z.size() < 4) throw std::invalid_argument("the response fit needs 4 or more samples");
  VecC Z(static_cast<Eigen::Index>(z.size())), F(Z.size());
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (!std::isfinite(z[i]) || !std::isfinite(f[i].real()) || !std::isfinite(f[i].imag()))
      throw std::invalid_argument("the response fit needs finite samples");
    Z[static_cast<Eigen::Index>(i)] = z[i];
    F[static_cast<Eigen::Index>(i)] = f[i];
  }
  const double scale = F.cwiseAbs().maxCoeff();
  const Barycentric b = aaa(Z, F, tolerance, max_degree);
  const std::vector<C> all = barycentric_poles(b);
  const VecC r_all = residues_for(Z, F, all);
  RationalFit fit;
  fit.aaa_degree = static_cast<int>(b.support.size());
  // A passive fluid's poles lie in the upper half plane; AAA's others are spurious (Froissart doublets, or poles
  // standing in for the far spectrum). Poles that contribute less than the tolerance go too.
  std::vector<C> kept;
  for (std::size_t j = 0; j < all.size(); ++j)
    if (all[j].imag() > 0 && contribution(Z, all[j], r_all[static_cast<Eigen::Index>(j)]) > tolerance * scale)
      kept.push_back(all[j]);
  fit.dropped_poles = static_cast<int>(all.size() - kept.size());
  if (kept.empty()) throw std::runtime_error("the response fit kept no pole in the upper half plane");
  const VecC r = residues_for(Z, F, kept);
  fit.poles = kept;
  fit.residues.assign(r.data(), r.data() + r.size());
  double err = 0;
  for (Eigen::Index i = 0; i < Z.size(); ++i) err = std::max(err, std::abs(F[i] - fit(Z[i])));
  fit.fit_error = err / scale;
  return fit;
}

}  // namespace rc::modes
