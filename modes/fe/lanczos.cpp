#include "lanczos.hpp"

#include "progress.hpp"

#include "eigen_dense.hpp"

#include <cmath>
#include <stdexcept>

namespace rc::modes {

LanczosProcess::LanczosProcess(const Eigen::VectorXd& weights, const Eigen::VectorXd& start, int max_steps)
    : weights_(weights), basis_(start.size(), std::max(max_steps, 1)) {
  norm0_ = std::sqrt(start.dot(weights_.cwiseProduct(start)));
  if (!(norm0_ > 0)) throw std::invalid_argument("Lanczos: zero start vector");
  basis_.col(0) = start / norm0_;
}

bool LanczosProcess::step(const Apply& apply) {
  const int j = steps();
  if (exhausted_ || j >= basis_.cols()) return false;
  progress_tick();  // a fine mesh's step can take seconds: the run's progress line keeps coming
  apply(basis_.col(j), v_);
  alpha_.push_back(basis_.col(j).dot(weights_.cwiseProduct(v_)));
  // Full re-orthogonalisation, twice: the spectra met here are dense, and plain Lanczos would lose
  // orthogonality and produce ghost copies of converged nodes.
  const auto Q = basis_.leftCols(j + 1);
  for (int pass = 0; pass < 2; ++pass) {
    h_.noalias() = Q.transpose() * weights_.cwiseProduct(v_);
    v_.noalias() -= Q * h_;
  }
  const double bnorm = std::sqrt(v_.dot(weights_.cwiseProduct(v_)));
  last_beta_ = bnorm;
  const double scale = std::abs(alpha_.back()) + (beta_.empty() ? 0.0 : beta_.back());
  if (!(bnorm > 1e-13 * std::max(scale, 1e-300))) { exhausted_ = true; last_beta_ = 0; return false; }
  if (j + 1 >= basis_.cols()) return false;
  beta_.push_back(bnorm);
  basis_.col(j + 1) = v_ / bnorm;
  return true;
}

std::vector<GaussNode> LanczosProcess::rule(double mass) const {
  const int k = steps();
  Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(alpha_.data(), k);
  Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(beta_.data(), std::max(k - 1, 0));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
  es.computeFromTridiagonal(d, e, Eigen::ComputeEigenvectors);
  if (es.info() != Eigen::Success) throw std::runtime_error("Lanczos: tridiagonal eigen-solve failed");
  std::vector<GaussNode> nodes(k);
  for (int i = 0; i < k; ++i) {
    nodes[i].lambda = es.eigenvalues()[i];
    nodes[i].E = mass * es.eigenvectors()(0, i) * es.eigenvectors()(0, i);
    nodes[i].residual = last_beta_ * std::abs(es.eigenvectors()(k - 1, i));
  }
  return nodes;
}

}  // namespace rc::modes
