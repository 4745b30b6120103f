// common/complex_svd.hpp and common/matrix_exponential.hpp against independent computations: Eigen's one-sided
// Jacobi SVD (another algorithm than LAPACK's divide and conquer) and closed-form exponentials.
#include "complex_svd.hpp"
#include "matrix_exponential.hpp"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <complex>
#include <stdexcept>
#include <utility>

namespace {

using cd = std::complex<double>;

Eigen::MatrixXcd seeded_matrix(int rows, int cols, unsigned seed) {
  std::srand(seed);
  return Eigen::MatrixXcd::Random(rows, cols);
}

TEST(ComplexSvd, ValuesAreJacobisOnTallSquareAndWideMatrices) {
  for (const auto& [m, n] : {std::pair{7, 7}, std::pair{40, 9}, std::pair{5, 30}}) {
    const Eigen::MatrixXcd A = seeded_matrix(m, n, static_cast<unsigned>(m * 100 + n));
    const Eigen::VectorXd s = rc::singular_values(A);
    const Eigen::VectorXd jacobi = Eigen::JacobiSVD<Eigen::MatrixXcd>(A).singularValues();
    ASSERT_EQ(s.size(), std::min(m, n));
    EXPECT_LT((s - jacobi).cwiseAbs().maxCoeff(), 1e-13 * jacobi(0)) << m << " x " << n;
    for (Eigen::Index i = 1; i < s.size(); ++i) EXPECT_GE(s(i - 1), s(i));  // largest first
  }
}

TEST(ComplexSvd, SmallestRightVectorIsTheNullVector) {
  // A rank-deficient tall matrix: its last column a combination of the others, so A v = 0 for a known v.
  Eigen::MatrixXcd A = seeded_matrix(12, 5, 7);
  const Eigen::VectorXcd c = Eigen::VectorXcd::Random(4);
  A.col(4) = A.leftCols(4) * c;
  Eigen::VectorXcd null(5);
  null << c, cd(-1);
  null.normalize();
  const Eigen::VectorXcd v = rc::smallest_right_singular_vector(A);
  EXPECT_NEAR(v.norm(), 1.0, 1e-14);
  EXPECT_LT((A * v).norm(), 1e-13 * A.norm());
  EXPECT_NEAR(std::abs(null.dot(v)), 1.0, 1e-12);  // the same direction, up to a phase
  // A full-rank matrix: |A v| is the smallest singular value, Jacobi's.
  const Eigen::MatrixXcd B = seeded_matrix(9, 6, 11);
  const Eigen::VectorXd jacobi = Eigen::JacobiSVD<Eigen::MatrixXcd>(B).singularValues();
  EXPECT_NEAR((B * rc::smallest_right_singular_vector(B)).norm(), jacobi(5), 1e-13 * jacobi(0));
}

TEST(ComplexSvd, RefusesWhatHasNoAnswer) {
  Eigen::MatrixXcd A = seeded_matrix(4, 4, 3);
  A(1, 2) = cd(std::nan(""), 0);
  EXPECT_THROW(rc::singular_values(A, "a test matrix"), std::runtime_error);
  EXPECT_THROW(rc::smallest_right_singular_vector(seeded_matrix(3, 5, 1)), std::invalid_argument);
}

TEST(MatrixExponential, RotationAndNilpotentClosedForms) {
  const double t = 0.7;
  Eigen::MatrixXd J(2, 2);
  J << 0, -t, t, 0;  // e^J is the rotation by t
  Eigen::MatrixXd R(2, 2);
  R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  EXPECT_LT((rc::matrix_exponential(J) - R).cwiseAbs().maxCoeff(), 1e-15);
  Eigen::MatrixXcd N = Eigen::MatrixXcd::Zero(3, 3);  // strictly upper triangular: e^N = I + N + N²/2
  N(0, 1) = cd(2, 1);
  N(1, 2) = cd(-1, 3);
  N(0, 2) = cd(0.5, 0);
  const Eigen::MatrixXcd expected = Eigen::MatrixXcd::Identity(3, 3) + N + N * N / 2.0;
  EXPECT_LT((rc::matrix_exponential(N) - expected).cwiseAbs().maxCoeff(), 1e-14);
  // A diagonal complex matrix: e^{i a}.
  const Eigen::MatrixXcd D = Eigen::VectorXcd::LinSpaced(4, cd(0, -2), cd(0, 3)).asDiagonal();
  const Eigen::MatrixXcd E = rc::matrix_exponential(D);
  for (int i = 0; i < 4; ++i) EXPECT_LT(std::abs(E(i, i) - std::exp(D(i, i))), 1e-14);
}

}  // namespace
