// Matrix products through the system BLAS (zgemm, dgemm; Debian's alternatives give OpenBLAS, which
// scripts/install-deps.sh installs): the Krylov response basis multiplies tall n × m blocks, where an optimised BLAS
// is several times faster than Eigen's portable kernels built without -march flags, and so is the 3-D survey's block
// Lanczos basis (real).
#pragma once

#include "eigen_dense.hpp"

namespace rc::modes {

// C = op(A) · B with op(A) = A or Aᴴ (`adjoint`). C is resized.
void blas_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, bool adjoint,
                  const Eigen::Ref<const Eigen::MatrixXcd>& B, Eigen::MatrixXcd& C);

// C −= A · B (C must have A.rows() × B.cols()).
void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::Ref<const Eigen::MatrixXcd>& B,
                           Eigen::Ref<Eigen::MatrixXcd> C);

// The real forms: C = op(A) · B with op(A) = A or Aᵀ (`transpose`), and C −= A · B.
void blas_product(const Eigen::Ref<const Eigen::MatrixXd>& A, bool transpose,
                  const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::MatrixXd& C);
void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                           Eigen::Ref<Eigen::MatrixXd> C);

}  // namespace rc::modes
