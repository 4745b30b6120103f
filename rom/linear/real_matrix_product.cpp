#include "real_matrix_product.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define RC_HAVE_AVX2_KERNEL 1
#endif

namespace rc::rom {
namespace {

#ifdef RC_HAVE_AVX2_KERNEL
// X = W C, W: m x k (leading dimension ldw), C: k x n (ldc), X: m x n (ldx), column-major. Blocks of
// 8 rows x 4 columns of X are held in eight AVX registers while k runs (one W column load of 8 values,
// four broadcasts of C and eight fused multiply-adds per k); leftover rows and columns are scalar.
// The rows i0..m of four columns that the 8-row blocks leave over (compiled for the same target as the kernel, so that
// its arithmetic, FMA contraction included, is the kernel's).
__attribute__((target("avx2,fma"))) void leftover_rows(const double* W, long ldw, const double* c0, long ldc, double* X,
                                                       long ldx, long i0, long m, long k) {
  const double* c1 = c0 + ldc;
  const double* c2 = c1 + ldc;
  const double* c3 = c2 + ldc;
  for (long i = i0; i < m; ++i) {
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (long q = 0; q < k; ++q) {
      const double wq = W[q * ldw + i];
      s0 += wq * c0[q];
      s1 += wq * c1[q];
      s2 += wq * c2[q];
      s3 += wq * c3[q];
    }
    X[i] = s0;
    X[ldx + i] = s1;
    X[2 * ldx + i] = s2;
    X[3 * ldx + i] = s3;
  }
}

// The columns j0..n that the 4-column blocks leave over.
__attribute__((target("avx2,fma"))) void leftover_columns(const double* W, long ldw, const double* C, long ldc,
                                                          double* X, long ldx, long m, long k, long j0, long n) {
  for (long j = j0; j < n; ++j)
    for (long i = 0; i < m; ++i) {
      double s = 0;
      for (long q = 0; q < k; ++q) s += W[q * ldw + i] * C[j * ldc + q];
      X[j * ldx + i] = s;
    }
}

__attribute__((target("avx2,fma"))) void product_avx2(const double* W, long ldw, const double* C, long ldc,
                                                      double* X, long ldx, long m, long k, long n) {
  long j = 0;
  for (; j + 4 <= n; j += 4) {
    const double* c0 = C + j * ldc;
    const double* c1 = c0 + ldc;
    const double* c2 = c1 + ldc;
    const double* c3 = c2 + ldc;
    long i = 0;
    for (; i + 8 <= m; i += 8) {
      __m256d a0 = _mm256_setzero_pd(), a1 = a0, a2 = a0, a3 = a0, b0 = a0, b1 = a0, b2 = a0, b3 = a0;
      const double* w = W + i;
      for (long q = 0; q < k; ++q, w += ldw) {
        const __m256d w0 = _mm256_loadu_pd(w), w1 = _mm256_loadu_pd(w + 4);
        __m256d s = _mm256_broadcast_sd(c0 + q);
        a0 = _mm256_fmadd_pd(w0, s, a0);
        b0 = _mm256_fmadd_pd(w1, s, b0);
        s = _mm256_broadcast_sd(c1 + q);
        a1 = _mm256_fmadd_pd(w0, s, a1);
        b1 = _mm256_fmadd_pd(w1, s, b1);
        s = _mm256_broadcast_sd(c2 + q);
        a2 = _mm256_fmadd_pd(w0, s, a2);
        b2 = _mm256_fmadd_pd(w1, s, b2);
        s = _mm256_broadcast_sd(c3 + q);
        a3 = _mm256_fmadd_pd(w0, s, a3);
        b3 = _mm256_fmadd_pd(w1, s, b3);
      }
      double* x = X + j * ldx + i;
      _mm256_storeu_pd(x, a0);
      _mm256_storeu_pd(x + 4, b0);
      x += ldx;
      _mm256_storeu_pd(x, a1);
      _mm256_storeu_pd(x + 4, b1);
      x += ldx;
      _mm256_storeu_pd(x, a2);
      _mm256_storeu_pd(x + 4, b2);
      x += ldx;
      _mm256_storeu_pd(x, a3);
      _mm256_storeu_pd(x + 4, b3);
    }
    leftover_rows(W, ldw, C + j * ldc, ldc, X + j * ldx, ldx, i, m, k);
  }
  leftover_columns(W, ldw, C, ldc, X, ldx, m, k, j, n);
}

bool cpu_has_avx2_fma() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}
#endif

}  // namespace

bool real_matrix_product_uses_avx2() {
#ifdef RC_HAVE_AVX2_KERNEL
  return cpu_has_avx2_fma();
#else
  return false;
#endif
}

void real_matrix_product(const Eigen::MatrixXd& W, const Eigen::Ref<const Eigen::MatrixXd>& C,
                         Eigen::Ref<Eigen::MatrixXd> X) {
#ifdef RC_HAVE_AVX2_KERNEL
  if (cpu_has_avx2_fma()) {
    product_avx2(W.data(), W.outerStride(), C.data(), C.outerStride(), X.data(), X.outerStride(), W.rows(),
                 W.cols(), C.cols());
    return;
  }
#endif
  X.noalias() = W * C;
}

}  // namespace rc::rom
