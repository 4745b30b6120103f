#include "reduced_transfer.hpp"

#include "complex_eigen.hpp"

#include <cmath>
#include <utility>

namespace rc::modes {

ReducedTransfer::ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op,
                                 const Eigen::MatrixXcd& left, const Eigen::MatrixXcd& right) {
  using cd = std::complex<double>;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(mass);
  const Eigen::MatrixXcd K = lu.solve(op);
  const Eigen::MatrixXcd Kr = lu.solve(right);
  if (K.allFinite()) {
    const ComplexEigen es = complex_eigen(K, true, "a reduced response pencil");
    const Eigen::MatrixXcd& V = es.vectors;
    out_poles_ = left.transpose() * V;
    in_poles_ = V.partialPivLu().solve(Kr);
    for (Eigen::Index j = 0; j < K.rows(); ++j) poles_.push_back(es.values[j]);
    // A probe off the spectrum, against a direct solve: the pole–residue form is trusted only where it agrees.
    double reach = 1;
    for (const cd p : poles_) reach = std::max(reach, std::abs(p));
    for (const cd probe : {cd(0.3 * reach, 0.2 * reach), cd(-0.7 * reach, 0.05 * reach)}) {
      const Eigen::MatrixXcd S = probe * mass - op;
      const Eigen::MatrixXcd exact = left.transpose() * S.partialPivLu().solve(right);
      const Eigen::MatrixXcd sum = matrix(probe);
      if (!((sum - exact).cwiseAbs().maxCoeff() <= 1e-9 * std::max(exact.cwiseAbs().maxCoeff(), 1e-300))) {
        poles_.clear();
        break;
      }
    }
  }
  if (!poles_.empty()) return;
  const Eigen::HessenbergDecomposition<Eigen::MatrixXcd> hess(K);
  T_ = hess.matrixH();
  const Eigen::MatrixXcd Q = hess.matrixQ();
  in_ = Q.adjoint() * Kr;
  out_ = left.transpose() * Q;
}

Eigen::MatrixXcd ReducedTransfer::matrix(std::complex<double> sigma) const {
  if (poles_.empty()) return hessenberg(sigma);
  Eigen::VectorXcd w(static_cast<Eigen::Index>(poles_.size()));
  for (std::size_t j = 0; j < poles_.size(); ++j) w[static_cast<Eigen::Index>(j)] = 1.0 / (sigma - poles_[j]);
  return out_poles_ * w.asDiagonal() * in_poles_;
}

// (σ − T) Y = in by Gaussian elimination with partial pivoting between neighbouring rows (the only subdiagonal is
// T's), then back substitution.
Eigen::MatrixXcd ReducedTransfer::hessenberg(std::complex<double> sigma) const {
  const Eigen::Index m = T_.rows();
  Eigen::MatrixXcd U = -T_;
  U.diagonal().array() += sigma;
  Eigen::MatrixXcd y = in_;
  for (Eigen::Index k = 0; k + 1 < m; ++k) {
    if (std::abs(U(k + 1, k)) > std::abs(U(k, k))) {
      U.row(k).tail(m - k).swap(U.row(k + 1).tail(m - k));
      y.row(k).swap(y.row(k + 1));
    }
    if (U(k + 1, k) == 0.0) continue;
    const std::complex<double> l = U(k + 1, k) / U(k, k);
    U.row(k + 1).tail(m - k) -= l * U.row(k).tail(m - k);
    y.row(k + 1) -= l * y.row(k);
  }
  U.triangularView<Eigen::Upper>().solveInPlace(y);
  return out_ * y;
}

}  // namespace rc::modes
