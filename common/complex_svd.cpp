#include "complex_svd.hpp"

#include <algorithm>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef RC_HAVE_LAPACK
extern "C" void zgesdd_(const char* jobz, const int* m, const int* n, std::complex<double>* a, const int* lda,
                        double* s, std::complex<double>* u, const int* ldu, std::complex<double>* vt, const int* ldvt,
                        std::complex<double>* work, const int* lwork, double* rwork, int* iwork, int* info,
                        std::size_t jobz_len);
#else
#include <Eigen/SVD>
#endif

namespace rc {
namespace {

struct Svd {
  Eigen::VectorXd values;
  Eigen::MatrixXcd vt;  // V^H, min(m, n) x n; empty unless asked for
};

void require_finite(const Eigen::MatrixXcd& A, const char* what) {
  if (!A.allFinite()) throw std::runtime_error(std::string(what) + " is not finite: no singular values");
}

#ifdef RC_HAVE_LAPACK
// zgesdd with jobz 'N' (values only) or 'S' (the thin factors; U is not kept).
Svd lapack_svd(const Eigen::MatrixXcd& A, bool vectors, const char* what) {
  const int m = static_cast<int>(A.rows()), n = static_cast<int>(A.cols()), k = std::min(m, n);
  Svd out;
  out.values.resize(k);
  Eigen::MatrixXcd a = A;  // zgesdd overwrites its input
  Eigen::MatrixXcd u(vectors ? m : 1, vectors ? k : 1);
  out.vt.resize(vectors ? k : 1, vectors ? n : 1);
  const char* jobz = vectors ? "S" : "N";
  const int ldu = vectors ? m : 1, ldvt = vectors ? k : 1;
  // rwork's size is LAPACK's documented minimum for each jobz (the larger bound of its two forms).
  const std::size_t mx = static_cast<std::size_t>(std::max(m, n)), mn = static_cast<std::size_t>(k);
  std::vector<double> rwork(vectors ? std::max(5 * mn * mn + 5 * mn, 2 * mx * mn + 2 * mn * mn + mn) : 7 * mn + 1);
  std::vector<int> iwork(8 * mn + 1);
  std::complex<double> query;
  int lwork = -1, info = 0;
  zgesdd_(jobz, &m, &n, a.data(), &m, out.values.data(), u.data(), &ldu, out.vt.data(), &ldvt, &query, &lwork,
          rwork.data(), iwork.data(), &info, 1);
  lwork = std::max(1, static_cast<int>(query.real()));
  std::vector<std::complex<double>> work(static_cast<std::size_t>(lwork));
  zgesdd_(jobz, &m, &n, a.data(), &m, out.values.data(), u.data(), &ldu, out.vt.data(), &ldvt, work.data(), &lwork,
          rwork.data(), iwork.data(), &info, 1);
  if (info != 0)
    throw std::runtime_error(std::string(what) + ": LAPACK zgesdd did not converge (info " + std::to_string(info) +
                             ")");
  return out;
}
#endif

Svd svd(const Eigen::MatrixXcd& A, bool vectors, const char* what) {
  require_finite(A, what);
  if (A.size() == 0) return {};
#ifdef RC_HAVE_LAPACK
  return lapack_svd(A, vectors, what);
#else
  const Eigen::BDCSVD<Eigen::MatrixXcd> s(A, vectors ? Eigen::ComputeThinV : 0);
  Svd out;
  out.values = s.singularValues();
  if (vectors) out.vt = s.matrixV().adjoint();
  return out;
#endif
}

}  // namespace

Eigen::VectorXd singular_values(const Eigen::MatrixXcd& A, const char* what) { return svd(A, false, what).values; }

Eigen::VectorXcd smallest_right_singular_vector(const Eigen::MatrixXcd& A, const char* what) {
  if (A.rows() < A.cols())
    throw std::invalid_argument(std::string(what) + ": fewer rows than columns, the null vector is not unique");
  const Svd s = svd(A, true, what);
  return s.vt.row(s.vt.rows() - 1).adjoint();
}

}  // namespace rc
