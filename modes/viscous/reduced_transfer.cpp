#include "reduced_transfer.hpp"

#include "complex_eigen.hpp"

#include <cmath>
#include <utility>

namespace rc::modes {

ReducedTransfer::ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op,
                                 const Eigen::VectorXcd& left, const Eigen::VectorXcd& right) {
  using cd = std::complex<double>;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(mass);
  const Eigen::MatrixXcd K = lu.solve(op);
  const Eigen::VectorXcd Kr = lu.solve(right);
  if (K.allFinite()) {
    const ComplexEigen es = complex_eigen(K, true, "a reduced response pencil");
    const Eigen::MatrixXcd& V = es.vectors;
    const Eigen::RowVectorXcd lV = left.transpose() * V;
    const Eigen::VectorXcd Vr = V.partialPivLu().solve(Kr);
    for (Eigen::Index j = 0; j < K.rows(); ++j) {
      poles_.push_back(es.values[j]);
      residues_.push_back(lV[j] * Vr[j]);
    }
    // A probe off the spectrum, against a direct solve: the pole–residue form is trusted only where it agrees.
    double reach = 1;
    for (const cd p : poles_) reach = std::max(reach, std::abs(p));
    for (const cd probe : {cd(0.3 * reach, 0.2 * reach), cd(-0.7 * reach, 0.05 * reach)}) {
      const Eigen::MatrixXcd S = probe * mass - op;
      const cd exact = (left.transpose() * S.partialPivLu().solve(right))(0);
      cd sum = 0;
      for (std::size_t j = 0; j < poles_.size(); ++j) sum += residues_[j] / (probe - poles_[j]);
      if (!(std::abs(sum - exact) <= 1e-9 * std::max(std::abs(exact), 1e-300))) {
        poles_.clear();
        residues_.clear();
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

std::complex<double> ReducedTransfer::operator()(std::complex<double> sigma) const {
  if (poles_.empty()) return hessenberg(sigma);
  std::complex<double> sum = 0;
  for (std::size_t j = 0; j < poles_.size(); ++j) sum += residues_[j] / (sigma - poles_[j]);
  return sum;
}

// (σ − T) y = in by Gaussian elimination with partial pivoting between neighbouring rows (the only subdiagonal is
// T's), then back substitution.
std::complex<double> ReducedTransfer::hessenberg(std::complex<double> sigma) const {
  const Eigen::Index m = T_.rows();
  Eigen::MatrixXcd U = -T_;
  U.diagonal().array() += sigma;
  Eigen::VectorXcd y = in_;
  for (Eigen::Index k = 0; k + 1 < m; ++k) {
    if (std::abs(U(k + 1, k)) > std::abs(U(k, k))) {
      U.row(k).tail(m - k).swap(U.row(k + 1).tail(m - k));
      std::swap(y[k], y[k + 1]);
    }
    if (U(k + 1, k) == 0.0) continue;
    const std::complex<double> l = U(k + 1, k) / U(k, k);
    U.row(k + 1).tail(m - k) -= l * U.row(k).tail(m - k);
    y[k + 1] -= l * y[k];
  }
  U.triangularView<Eigen::Upper>().solveInPlace(y);
  return (out_ * y)(0);
}

}  // namespace rc::modes
