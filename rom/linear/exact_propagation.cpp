#include "exact_propagation.hpp"

#include "balancing.hpp"
#include "complex_svd.hpp"
#include "real_matrix_product.hpp"

#include "eigen_dense.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <thread>
#include <vector>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

// The 2-norm condition number of the eigenvectors, real or complex: both through LAPACK's complex SVD
// (common/complex_svd.hpp; an Eigen SVD of its own cost this file about 60 s of compile time).
double condition_of(const Eigen::MatrixXcd& V) {
  const Eigen::VectorXd sv = singular_values(V, "the eigenvector matrix");
  return sv(0) / sv(sv.size() - 1);
}

// The real matrix A = T(-iB)T^{-1}, T = diag(-i I_n, I, I), of an undamped first-order system.
Eigen::MatrixXd real_form_of(const FirstOrderSystem& f) {
  Eigen::MatrixXcd A = cd(0, -1) * f.B;
  A.topRows(f.n) *= cd(0, -1);
  A.leftCols(f.n) *= cd(0, 1);
  return A.real();
}

// Modal coefficients of y0: c = W^{-1} T y0 (real form) or V^{-1} y0.
Eigen::VectorXcd coefficients(const ModalForm& f, const Eigen::VectorXcd& y0) {
  if (!f.real) return Eigen::PartialPivLU<Eigen::MatrixXcd>(f.V).solve(y0);
  Eigen::VectorXcd x = y0;
  x.head(f.n) *= cd(0, -1);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(f.W);
  const Eigen::VectorXd re = lu.solve(Eigen::VectorXd(x.real())), im = lu.solve(Eigen::VectorXd(x.imag()));
  return re.cast<cd>() + cd(0, 1) * im.cast<cd>();
}

// e^{mu_i t} (mu = i sigma in the real form).
Eigen::VectorXcd exponentials(const ModalForm& f, double t) {
  const Eigen::Index D = f.real ? f.sigma.size() : f.mu.size();
  Eigen::VectorXcd e(D);
  for (Eigen::Index i = 0; i < D; ++i) e[i] = f.real ? std::exp(cd(0, f.sigma[i] * t)) : std::exp(f.mu[i] * t);
  return e;
}

}  // namespace

ModalForm modal_form(const FirstOrderSystem& f, bool undamped, double real_tolerance) {
  ModalForm mf;
  mf.n = f.n;
  // Both paths balance the matrix first (balancing.hpp): the eigen-solvers' error is ~eps |B|.
  if (undamped) {
    Eigen::MatrixXd A = real_form_of(f);
    const Eigen::VectorXd S = balance_in_place(A);
    Eigen::EigenSolver<Eigen::MatrixXd> es(A, true);
    // Real Schur form: a root is real exactly when it comes as a 1x1 block (imaginary part 0); a
    // pair of roots closer than rounding comes as a 2x2 block and takes the complex path below.
    if (es.info() == Eigen::Success && es.eigenvalues().imag().cwiseAbs().maxCoeff() == 0) {
      mf.real = true;
      mf.W = S.asDiagonal() * es.pseudoEigenvectors();  // real eigenvectors when all eigenvalues are real
      mf.W.colwise().normalize();  // unit columns again after the unbalancing (keeps cond(W) honest)
      mf.sigma = es.eigenvalues().real();
      mf.condition = condition_of(mf.W.cast<cd>());
      mf.usable = std::isfinite(mf.condition) && mf.condition < kMaxEigvecCondition;
      mf.undamped_real = true;
      if (mf.usable) return mf;
      mf = ModalForm{};
      mf.n = f.n;
    }
  }
  Eigen::MatrixXcd B = f.B;
  const Eigen::VectorXd S = balance_in_place(B);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> es(B, true);
  if (es.info() != Eigen::Success) return mf;
  mf.V = S.asDiagonal() * es.eigenvectors();
  mf.V.colwise().normalize();
  mf.mu = es.eigenvalues();
  mf.condition = condition_of(mf.V);
  mf.usable = std::isfinite(mf.condition) && mf.condition < kMaxEigvecCondition;
  const double radius = mf.mu.cwiseAbs().maxCoeff();
  mf.undamped_real = undamped && mf.mu.real().cwiseAbs().maxCoeff() <= real_tolerance * std::max(radius, 1e-300);
  return mf;
}

void snap_to_imaginary_axis(ModalForm& f) {
  for (Eigen::Index i = 0; i < f.mu.size(); ++i) f.mu[i] = cd(0, f.mu[i].imag());
}

Eigen::VectorXcd modal_state_at(const ModalForm& f, const Eigen::VectorXcd& y0, double t) {
  const Eigen::VectorXcd ce = exponentials(f, t).cwiseProduct(coefficients(f, y0));
  if (!f.real) return f.V * ce;
  Eigen::VectorXcd y = f.W.cast<cd>() * ce;
  y.head(f.n) *= cd(0, 1);  // y = T^{-1} x
  return y;
}

void modal_states(const ModalForm& f, const Eigen::VectorXcd& y0, double h, long steps,
                  const StateBlockSink& sink, int threads) {
  const Eigen::VectorXcd c = coefficients(f, y0);
  const Eigen::Index D = c.size();
  // j = q K + r: e^{mu j h} = e^{mu (qK h)} e^{mu (r h)}; each factor is evaluated directly, so the
  // product carries two roundings whatever j is (no recurrence, nothing accumulates).
  const long total = steps + 1;
  const long K = std::clamp(static_cast<long>(std::ceil(std::sqrt(static_cast<double>(total)))), 16L, 2048L);
  Eigen::MatrixXcd low(D, K);  // e^{mu r h} c
  for (long r = 0; r < K; ++r) low.col(r) = exponentials(f, static_cast<double>(r) * h).cwiseProduct(c);
  const long blocks = (total + K - 1) / K;
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<long>(threads, blocks));

  std::atomic<long> next{0};
  auto worker = [&]() {
    Eigen::MatrixXcd Y(D, K);
    Eigen::MatrixXd coeff(D, 2 * K), X(D, 2 * K), re(D, K), im(D, K);
    Eigen::VectorXcd high(D);
    for (long q; (q = next.fetch_add(1)) < blocks;) {
      const long j0 = q * K, cols = std::min(K, total - j0);
      high = exponentials(f, static_cast<double>(j0) * h);
      if (f.real) {
        // [Re | Im] of e^{i sigma t_j} c, then one real product with W.
        for (long r = 0; r < cols; ++r)
          for (Eigen::Index i = 0; i < D; ++i) {
            const cd e = high[i] * low(i, r);
            coeff(i, r) = e.real();
            coeff(i, cols + r) = e.imag();
          }
        real_matrix_product(f.W, coeff.leftCols(2 * cols), X.leftCols(2 * cols));
        // y = T^{-1} x: the s*u rows times i, (a + ib) i = -b + ia.
        X.topLeftCorner(f.n, cols).swap(X.block(0, cols, f.n, cols));
        X.topLeftCorner(f.n, cols) *= -1.0;
        sink(j0, X.leftCols(cols), X.middleCols(cols, cols));
      } else {
        Y.leftCols(cols).noalias() = f.V * (high.asDiagonal() * low.leftCols(cols));
        re.leftCols(cols) = Y.leftCols(cols).real();
        im.leftCols(cols) = Y.leftCols(cols).imag();
        sink(j0, re.leftCols(cols), im.leftCols(cols));
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
}

}  // namespace rc::rom
