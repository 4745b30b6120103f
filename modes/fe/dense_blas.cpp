#include "dense_blas.hpp"

#include <complex>
#include <stdexcept>

extern "C" void zgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const std::complex<double>* alpha, const std::complex<double>* a, const int* lda,
                       const std::complex<double>* b, const int* ldb, const std::complex<double>* beta,
                       std::complex<double>* c, const int* ldc);
extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace rc::modes {
namespace {

void call_gemm(const char* ta, const char* tb, const int* m, const int* n, const int* k,
               const std::complex<double>* alpha, const std::complex<double>* a, const int* lda,
               const std::complex<double>* b, const int* ldb,
               const std::complex<double>* beta, std::complex<double>* c, const int* ldc) {
  zgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}
void call_gemm(const char* ta, const char* tb, const int* m, const int* n, const int* k, const double* alpha,
               const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
               const int* ldc) {
  dgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

template <class Scalar>
void gemm(char ta, const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& A,
          const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& B, Scalar alpha, Scalar beta, Scalar* C, int ldc) {
  const int m = static_cast<int>(ta == 'N' ? A.rows() : A.cols());
  const int k = static_cast<int>(ta == 'N' ? A.cols() : A.rows());
  const int n = static_cast<int>(B.cols());
  if (B.rows() != k) throw std::logic_error("blas_product: inner dimensions differ");
  if (m == 0 || n == 0) return;
  const int lda = std::max(1, static_cast<int>(A.outerStride())), ldb = std::max(1, static_cast<int>(B.outerStride()));
  const char tb = 'N';
  call_gemm(&ta, &tb, &m, &n, &k, &alpha, A.data(), &lda, B.data(), &ldb, &beta, C, &ldc);
}

template <class Scalar>
void product(const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& A, char op,
             const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& B, Eigen::Matrix<Scalar, -1, -1>& C) {
  C.setZero(op == 'N' ? A.rows() : A.cols(), B.cols());
  if (A.rows() == 0 || A.cols() == 0) return;
  gemm<Scalar>(op, A, B, 1.0, 0.0, C.data(), static_cast<int>(std::max<Eigen::Index>(1, C.rows())));
}

template <class Scalar>
void subtract_product(const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& A,
                      const Eigen::Ref<const Eigen::Matrix<Scalar, -1, -1>>& B,
                      Eigen::Ref<Eigen::Matrix<Scalar, -1, -1>> C) {
  if (A.cols() == 0) return;
  gemm<Scalar>('N', A, B, -1.0, 1.0, C.data(), static_cast<int>(std::max<Eigen::Index>(1, C.outerStride())));
}

}  // namespace

void blas_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, bool adjoint,
                  const Eigen::Ref<const Eigen::MatrixXcd>& B, Eigen::MatrixXcd& C) {
  product<std::complex<double>>(A, adjoint ? 'C' : 'N', B, C);
}

void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::Ref<const Eigen::MatrixXcd>& B,
                           Eigen::Ref<Eigen::MatrixXcd> C) {
  subtract_product<std::complex<double>>(A, B, C);
}

void blas_product(const Eigen::Ref<const Eigen::MatrixXd>& A, bool transpose,
                  const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::MatrixXd& C) {
  product<double>(A, transpose ? 'T' : 'N', B, C);
}

void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                           Eigen::Ref<Eigen::MatrixXd> C) {
  subtract_product<double>(A, B, C);
}

}  // namespace rc::modes
