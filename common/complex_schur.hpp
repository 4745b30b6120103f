// The complex Schur form A = Z T Zᴴ (T upper triangular, Z unitary) of a dense complex matrix: LAPACK's zgees when
// the build found LAPACK (blocked Hessenberg reduction and multishift QR), else Eigen's ComplexSchur. Where a pencil's
// eigenvectors are too ill-conditioned for its pole–residue form, the Schur form still gives its transfer function
// stably, one triangular solve per frequency (modes/viscous/reduced_transfer.hpp). Not for concurrent use from
// several threads (complex_eigen.hpp says why).
#pragma once

#include "eigen_dense.hpp"

namespace rc {

struct ComplexSchurForm {
  Eigen::MatrixXcd T;  // upper triangular: the eigenvalues on its diagonal
  Eigen::MatrixXcd Z;  // unitary: A = Z T Zᴴ
};

// Throws std::runtime_error when the QR iteration does not converge, or naming `what` when A is not finite.
ComplexSchurForm complex_schur(const Eigen::MatrixXcd& A, const char* what);

}  // namespace rc
