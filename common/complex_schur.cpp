#include "complex_schur.hpp"

#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef RC_HAVE_LAPACK
// SELECT and BWORK are not referenced with SORT = 'N' (LAPACK's zgees documentation).
extern "C" void zgees_(const char* jobvs, const char* sort, int (*select)(const std::complex<double>*), const int* n,
                       std::complex<double>* a, const int* lda, int* sdim, std::complex<double>* w,
                       std::complex<double>* vs, const int* ldvs, std::complex<double>* work, const int* lwork,
                       double* rwork, int* bwork, int* info, std::size_t jobvs_len, std::size_t sort_len);
#endif

namespace rc {

ComplexSchurForm complex_schur(const Eigen::MatrixXcd& A, const char* what) {
  ComplexSchurForm out;
  const int n = static_cast<int>(A.rows());
  if (n == 0) return out;
  // The QR iteration does not return on infinite or NaN entries (as complex_eigen's).
  if (!A.allFinite()) throw std::runtime_error(std::string(what) + " is not finite: no Schur form");
#ifdef RC_HAVE_LAPACK
  out.T = A;  // zgees overwrites its input with T
  out.Z.resize(n, n);
  Eigen::VectorXcd w(n);
  std::vector<double> rwork(static_cast<std::size_t>(n));
  std::complex<double> query;
  int sdim = 0, info = 0, lwork = -1, bwork = 0;
  zgees_("V", "N", nullptr, &n, out.T.data(), &n, &sdim, w.data(), out.Z.data(), &n, &query, &lwork, rwork.data(),
         &bwork, &info, 1, 1);
  lwork = std::max(1, static_cast<int>(query.real()));
  std::vector<std::complex<double>> work(static_cast<std::size_t>(lwork));
  zgees_("V", "N", nullptr, &n, out.T.data(), &n, &sdim, w.data(), out.Z.data(), &n, work.data(), &lwork,
         rwork.data(), &bwork, &info, 1, 1);
  if (info != 0)
    throw std::runtime_error(std::string(what) + ": Schur form (LAPACK zgees) did not converge (info " +
                             std::to_string(info) + ")");
  out.T.triangularView<Eigen::StrictlyLower>().setZero();
#else
  Eigen::ComplexSchur<Eigen::MatrixXcd> schur(A);
  if (schur.info() != Eigen::Success) throw std::runtime_error(std::string(what) + ": Schur form did not converge");
  out.T = schur.matrixT();
  out.Z = schur.matrixU();
#endif
  return out;
}

}  // namespace rc
