#include "krein_gap.hpp"

#include "characteristic.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace rc::rom {

int krein_signature(const ChainModel& m, double sigma) {
  const Eigen::MatrixXcd phi = characteristic_matrix(m, sigma);
  if (!phi.allFinite()) return 0;  // at a pole of (22): a mode the chain does not feel
  const Eigen::MatrixXd sym = 0.5 * (phi.real() + phi.real().transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(sym);
  if (es.info() != Eigen::Success) return 0;
  // The eigenvalue through zero, and how clearly it is alone there: a second eigenvalue as small means a multiple
  // root (a collision in progress), whose signature is not one sign.
  const Eigen::VectorXd mu = es.eigenvalues();
  Eigen::Index k = 0;
  for (Eigen::Index j = 1; j < mu.size(); ++j)
    if (std::abs(mu[j]) < std::abs(mu[k])) k = j;
  for (Eigen::Index j = 0; j < mu.size(); ++j)
    if (j != k && std::abs(mu[j]) <= 100 * std::abs(mu[k])) return 0;
  const Eigen::VectorXd v = es.eigenvectors().col(k);
  const double slope = v.dot(characteristic_derivative(m, sigma).real() * v);
  if (!std::isfinite(slope) || slope == 0) return 0;
  return slope > 0 ? 1 : -1;
}

KreinGap krein_gap(const ChainModel& m, const Eigen::VectorXcd& sigma, double tolerance) {
  KreinGap g;
  if (m.dissipative()) return g;
  std::vector<std::pair<double, int>> signed_roots;  // (σ, signature), away from σ = 0
  for (Eigen::Index j = 0; j < sigma.size(); ++j) {
    if (std::abs(sigma[j].imag()) > tolerance) return g;  // unstable: the margin is |Im σ|, not a gap
    if (std::abs(sigma[j]) <= tolerance) continue;
    const int s = krein_signature(m, sigma[j].real());
    if (s != 0) signed_roots.emplace_back(sigma[j].real(), s);
  }
  g.signed_roots = static_cast<int>(signed_roots.size());
  std::sort(signed_roots.begin(), signed_roots.end());
  for (size_t j = 1; j < signed_roots.size(); ++j) {
    const auto& [a, sa] = signed_roots[j - 1];
    const auto& [b, sb] = signed_roots[j];
    if (sa == sb || (g.defined && b - a >= g.gap)) continue;
    g = KreinGap{true, b - a, a, b, g.signed_roots};
  }
  return g;
}

}  // namespace rc::rom
