// The matrix exponential e^A of a dense real or complex matrix: Eigen's scaling and squaring with a Padé
// approximant (unsupported/Eigen/MatrixFunctions; Higham, "The scaling and squaring method for the matrix
// exponential revisited", 2005), compiled once here. Each file that called A.exp() itself compiled its own copy of
// that template code, about 4 s a matrix type at -O3 in each of five of chain-rom's files (docs/benchmarks.md,
// "Build time").
#pragma once

#include <Eigen/Core>

namespace rc {

Eigen::MatrixXd matrix_exponential(const Eigen::MatrixXd& A);
Eigen::MatrixXcd matrix_exponential(const Eigen::MatrixXcd& A);

}  // namespace rc
