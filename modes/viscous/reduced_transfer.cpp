#include "reduced_transfer.hpp"

#include "complex_eigen.hpp"
#include "complex_schur.hpp"

#include <cmath>
#include <utility>

namespace rc::modes {

ReducedTransfer::ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op,
                                 const Eigen::MatrixXcd& left, const Eigen::MatrixXcd& right, bool try_poles) {
  using cd = std::complex<double>;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(mass);
  const Eigen::MatrixXcd K = lu.solve(op);
  const Eigen::MatrixXcd Kr = lu.solve(right);
  if (try_poles && K.allFinite()) {
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
  const ComplexSchurForm schur = complex_schur(K, "a reduced response pencil");
  T_ = schur.T;
  in_ = schur.Z.adjoint() * Kr;
  out_ = left.transpose() * schur.Z;
}

Eigen::MatrixXcd ReducedTransfer::matrix(std::complex<double> sigma) const {
  if (poles_.empty()) return schur(sigma);
  Eigen::VectorXcd w(static_cast<Eigen::Index>(poles_.size()));
  for (std::size_t j = 0; j < poles_.size(); ++j) w[static_cast<Eigen::Index>(j)] = 1.0 / (sigma - poles_[j]);
  return out_poles_ * w.asDiagonal() * in_poles_;
}

// (σ − T) y = Zᴴ𝓜⁻¹R by back substitution: y_i = (b_i + Σ_{j>i} T_ij y_j) / (σ − T_ii), T's row i read once for
// every input. The diagonal is never zero at a σ off the spectrum (σ = T_ii is a pole: the entries are then inf).
Eigen::MatrixXcd ReducedTransfer::schur(std::complex<double> sigma) const {
  const Eigen::Index m = T_.rows(), p = in_.cols();
  Eigen::MatrixXcd y = in_;
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    const auto row = T_.row(i).tail(m - 1 - i);
    for (Eigen::Index c = 0; c < p; ++c)
      y(i, c) = (y(i, c) + row.transpose().cwiseProduct(y.col(c).tail(m - 1 - i)).sum()) / (sigma - T_(i, i));
  }
  return out_ * y;
}

}  // namespace rc::modes
