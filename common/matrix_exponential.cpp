#include "matrix_exponential.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace rc {

Eigen::MatrixXd matrix_exponential(const Eigen::MatrixXd& A) { return A.exp(); }

Eigen::MatrixXcd matrix_exponential(const Eigen::MatrixXcd& A) { return A.exp(); }

}  // namespace rc
