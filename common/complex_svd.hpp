// Singular values of a dense complex matrix, and the right singular vector of the smallest one: LAPACK's zgesdd
// (divide and conquer, the algorithm of Eigen's BDCSVD) when the build found LAPACK, else Eigen's BDCSVD. Through
// LAPACK because Eigen's BDCSVD<MatrixXcd> cost 37-60 s of compile time for its one explicit instantiation
// (docs/benchmarks.md, "Build time"), the largest single unit of the build, for three callers: a condition number
// (rom/linear/exact_propagation.cpp), the smallest singular value of Φ (rom/model/characteristic.cpp) and the
// AAA fit's null vector (modes/viscous/rational_fit.cpp). Not for concurrent use from several threads (see
// complex_eigen.hpp).
#pragma once

#include <Eigen/Core>

namespace rc {

// All min(rows, cols) singular values, largest first. Throws std::runtime_error, naming `what`, when A is not
// finite or the iteration does not converge.
Eigen::VectorXd singular_values(const Eigen::MatrixXcd& A, const char* what = "the matrix");

// The right singular vector of A's smallest singular value (unit 2-norm): the least-squares null vector
// min |A v| over |v| = 1, of a matrix with at least as many rows as columns.
Eigen::VectorXcd smallest_right_singular_vector(const Eigen::MatrixXcd& A, const char* what = "the matrix");

}  // namespace rc
