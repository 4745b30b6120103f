#include "complex_eigen.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef RC_HAVE_LAPACK
extern "C" void zgeev_(const char* jobvl, const char* jobvr, const int* n, std::complex<double>* a, const int* lda,
                       std::complex<double>* w, std::complex<double>* vl, const int* ldvl, std::complex<double>* vr,
                       const int* ldvr, std::complex<double>* work, const int* lwork, double* rwork, int* info,
                       std::size_t jobvl_len, std::size_t jobvr_len);
extern "C" void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda, double* wr,
                       double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr, double* work,
                       const int* lwork, int* info, std::size_t jobvl_len, std::size_t jobvr_len);
#endif

namespace rc {

ComplexEigen complex_eigen(const Eigen::MatrixXcd& A, bool vectors, const char* what) {
  ComplexEigen out;
  const int n = static_cast<int>(A.rows());
  if (n == 0) return out;
  // LAPACK's QR iteration does not return on infinite or NaN entries (a fuzzed table looped for minutes).
  if (!A.allFinite()) throw std::runtime_error(std::string(what) + " is not finite: no eigenvalues");
#ifdef RC_HAVE_LAPACK
  Eigen::MatrixXcd a = A;  // zgeev overwrites its input
  out.values.resize(n);
  if (vectors) out.vectors.resize(n, n);
  std::vector<double> rwork(2 * static_cast<std::size_t>(n));
  std::complex<double> query, dummy;
  const int one = 1, ldvr = vectors ? n : 1;
  int lwork = -1, info = 0;
  const char* jobvr = vectors ? "V" : "N";
  std::complex<double>* vr = vectors ? out.vectors.data() : &dummy;
  zgeev_("N", jobvr, &n, a.data(), &n, out.values.data(), &dummy, &one, vr, &ldvr, &query, &lwork, rwork.data(),
         &info, 1, 1);
  lwork = std::max(1, static_cast<int>(query.real()));
  std::vector<std::complex<double>> work(static_cast<std::size_t>(lwork));
  zgeev_("N", jobvr, &n, a.data(), &n, out.values.data(), &dummy, &one, vr, &ldvr, work.data(), &lwork,
         rwork.data(), &info, 1, 1);
  if (info != 0)
    throw std::runtime_error("eigen-solver (LAPACK zgeev) did not converge (info " + std::to_string(info) + ")");
#else
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(A, vectors);
  if (es.info() != Eigen::Success) throw std::runtime_error("eigen-solver did not converge");
  out.values = es.eigenvalues();
  if (vectors) out.vectors = es.eigenvectors();
#endif
  return out;
}

ComplexEigen real_eigen(const Eigen::MatrixXd& A, bool vectors, const char* what) {
  ComplexEigen out;
  const int n = static_cast<int>(A.rows());
  if (n == 0) return out;
  if (!A.allFinite()) throw std::runtime_error(std::string(what) + " is not finite: no eigenvalues");
#ifdef RC_HAVE_LAPACK
  Eigen::MatrixXd a = A, vr(vectors ? n : 1, vectors ? n : 1);
  Eigen::VectorXd wr(n), wi(n);
  double query = 0, dummy = 0;
  const int one = 1, ldvr = vectors ? n : 1;
  int lwork = -1, info = 0;
  const char* jobvr = vectors ? "V" : "N";
  dgeev_("N", jobvr, &n, a.data(), &n, wr.data(), wi.data(), &dummy, &one, vr.data(), &ldvr, &query, &lwork, &info,
         1, 1);
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dgeev_("N", jobvr, &n, a.data(), &n, wr.data(), wi.data(), &dummy, &one, vr.data(), &ldvr, work.data(), &lwork,
         &info, 1, 1);
  if (info != 0)
    throw std::runtime_error(std::string(what) + ": LAPACK dgeev did not converge (info " + std::to_string(info) + ")");
  out.values.resize(n);
  for (int i = 0; i < n; ++i) out.values(i) = {wr(i), wi(i)};
  if (vectors) {
    out.vectors.resize(n, n);
    for (int i = 0; i < n; ++i) {
      if (wi(i) != 0 && i + 1 < n) {  // a pair: columns i, i+1 hold the real and imaginary parts
        out.vectors.col(i) = vr.col(i).cast<std::complex<double>>() + std::complex<double>(0, 1) * vr.col(i + 1);
        out.vectors.col(i + 1) = out.vectors.col(i).conjugate();
        ++i;
      } else {
        out.vectors.col(i) = vr.col(i).cast<std::complex<double>>();
      }
    }
  }
#else
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, vectors);
  if (es.info() != Eigen::Success) throw std::runtime_error(std::string(what) + ": the eigen-solver did not converge");
  out.values = es.eigenvalues();
  if (vectors) out.vectors = es.eigenvectors();
#endif
  return out;
}

}  // namespace rc
