#include "dense_blas.hpp"

#include <complex>
#include <stdexcept>

extern "C" void zgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const std::complex<double>* alpha, const std::complex<double>* a, const int* lda,
                       const std::complex<double>* b, const int* ldb, const std::complex<double>* beta,
                       std::complex<double>* c, const int* ldc);

namespace rc::modes {
namespace {

void gemm(char ta, const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::Ref<const Eigen::MatrixXcd>& B,
          std::complex<double> alpha, std::complex<double> beta, std::complex<double>* C, int ldc) {
  const int m = static_cast<int>(ta == 'N' ? A.rows() : A.cols());
  const int k = static_cast<int>(ta == 'N' ? A.cols() : A.rows());
  const int n = static_cast<int>(B.cols());
  if (B.rows() != k) throw std::logic_error("blas_product: inner dimensions differ");
  if (m == 0 || n == 0) return;
  const int lda = std::max(1, static_cast<int>(A.outerStride())), ldb = std::max(1, static_cast<int>(B.outerStride()));
  const char tb = 'N';
  zgemm_(&ta, &tb, &m, &n, &k, &alpha, A.data(), &lda, B.data(), &ldb, &beta, C, &ldc);
}

}  // namespace

void blas_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, bool adjoint,
                  const Eigen::Ref<const Eigen::MatrixXcd>& B, Eigen::MatrixXcd& C) {
  C.setZero(adjoint ? A.cols() : A.rows(), B.cols());
  if (A.rows() == 0 || A.cols() == 0) return;
  gemm(adjoint ? 'C' : 'N', A, B, 1.0, 0.0, C.data(), static_cast<int>(std::max<Eigen::Index>(1, C.rows())));
}

void blas_subtract_product(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::Ref<const Eigen::MatrixXcd>& B,
                           Eigen::Ref<Eigen::MatrixXcd> C) {
  if (A.cols() == 0) return;
  gemm('N', A, B, -1.0, 1.0, C.data(), static_cast<int>(std::max<Eigen::Index>(1, C.outerStride())));
}

}  // namespace rc::modes
