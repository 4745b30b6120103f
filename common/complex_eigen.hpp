// Eigenvalues and right eigenvectors of a dense complex matrix (the first-order system of `chain-rom spectrum`, the
// reduced pencils of cavity-modes' Krylov response tables):
// LAPACK's zgeev when the build found LAPACK (Debian's liblapack, OpenBLAS's where installed: multishift QR with
// aggressive early deflation, 3-4 times faster than Eigen's ComplexEigenSolver at the 260 unknowns of a chain with
// three response-fit tables; docs/benchmarks.md), else Eigen's. Not for concurrent use from several threads (a
// single-threaded OpenBLAS need not be thread-safe): the sweep's threads keep Eigen (spectrum.hpp, compute_verdict).
#pragma once

#include "eigen_dense.hpp"

namespace rc {

struct ComplexEigen {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;  // unit 2-norm columns; empty unless asked for
};

// Throws std::runtime_error when the QR iteration does not converge, or naming `what` when A is not finite.
ComplexEigen complex_eigen(const Eigen::MatrixXcd& A, bool vectors,
                           const char* what = "the first-order matrix of (26)");

// The same for a dense real matrix (LAPACK's dgeev, else Eigen's EigenSolver): complex values and vectors, a
// complex pair's vectors unpacked from LAPACK's real storage. Used for the companion form of a partially filled
// tank's quartic (modes/freesurface/free_surface_mesh.hpp).
ComplexEigen real_eigen(const Eigen::MatrixXd& A, bool vectors, const char* what);

}  // namespace rc
