// Complex matrix products through the system BLAS (zgemm; Debian's alternatives give OpenBLAS, which
// scripts/install-deps.sh installs): the Krylov response basis multiplies tall n × m blocks, where an optimised BLAS
// is several times faster than Eigen's portable kernels built without -march flags.
#pragma once

#include "eigen_dense.hpp"

namespace rc::modes {

// C = op(A) · B with op(A) = A or Aᴴ (`adjoint`). C is resized.
void blas_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, bool adjoint,
                  const Eigen::Ref<const Eigen::MatrixXcd>& B, Eigen::MatrixXcd& C);

// C −= A · B (C must have A.rows() × B.cols()).
void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::Ref<const Eigen::MatrixXcd>& B,
                           Eigen::Ref<Eigen::MatrixXcd> C);

}  // namespace rc::modes
