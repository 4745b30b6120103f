#include "krein_gap.hpp"

#include "characteristic.hpp"

#include "eigen_dense.hpp"
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
  std::vector<double> real;  // the real roots away from σ = 0, ascending
  for (Eigen::Index j = 0; j < sigma.size(); ++j) {
    if (std::abs(sigma[j].imag()) > tolerance) return g;  // unstable: the margin is |Im σ|, not a gap
    if (std::abs(sigma[j]) > tolerance) real.push_back(sigma[j].real());
  }
  std::sort(real.begin(), real.end());
  // Signatures are read lazily, closest neighbours first: the first adjacent pair of opposite signature in order of
  // distance is the gap, and most maps find it after a few of the roots (a sweep evaluates every point).
  std::vector<int> signature(real.size(), 2);  // 2: not read yet; 0: unreadable (a pole, a multiple root)
  const auto sign_of = [&](std::size_t i) {
    if (signature[i] == 2) signature[i] = krein_signature(m, real[i]);
    return signature[i];
  };
  std::vector<std::size_t> pairs;  // pair i: roots i and i + 1
  for (std::size_t i = 0; i + 1 < real.size(); ++i) pairs.push_back(i);
  std::sort(pairs.begin(), pairs.end(), [&](std::size_t a, std::size_t b) {
    return real[a + 1] - real[a] < real[b + 1] - real[b];
  });
  bool unreadable = false;
  for (const std::size_t i : pairs) {
    const int a = sign_of(i), b = sign_of(i + 1);
    unreadable = unreadable || a == 0 || b == 0;
    if (a == 0 || b == 0 || a == b) continue;
    // Closer pairs all read: the gap, unless an unreadable root among them leaves its two neighbours, straddling it,
    // as a pair not yet looked at (then every pair of readable neighbours below).
    if (!unreadable) return KreinGap{true, real[i + 1] - real[i], real[i], real[i + 1]};
    break;
  }
  std::vector<std::size_t> readable;
  for (std::size_t i = 0; i < real.size(); ++i)
    if (sign_of(i) != 0) readable.push_back(i);
  for (std::size_t j = 1; j < readable.size(); ++j) {
    const std::size_t a = readable[j - 1], b = readable[j];
    if (signature[a] == signature[b] || (g.defined && real[b] - real[a] >= g.gap)) continue;
    g = KreinGap{true, real[b] - real[a], real[a], real[b]};
  }
  return g;
}

}  // namespace rc::rom
