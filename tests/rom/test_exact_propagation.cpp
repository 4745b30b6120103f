// Exact propagation's machinery (exact_propagation.hpp): the AVX2 matrix product against Eigen's,
// balancing, and the block evaluation of many output times against the state at one time.
#include "balancing.hpp"
#include "exact_propagation.hpp"
#include "real_matrix_product.hpp"
#include "rom_test_util.hpp"

#include <gtest/gtest.h>

#include <mutex>

using namespace rc::rom;
using namespace rc::rom::test;
using cd = std::complex<double>;

// Every shape the kernel splits differently (rows: blocks of 8 and leftovers; columns: blocks of 4 and
// leftovers), and a column block of a wider matrix (the strides exact propagation passes).
TEST(ExactPropagation, RealMatrixProductMatchesEigen) {
  double worst = 0;
  for (int m : {1, 3, 8, 9, 17, 66})
    for (int n : {1, 4, 5, 11}) {
      const Eigen::MatrixXd W = Eigen::MatrixXd::Random(m, m), C = Eigen::MatrixXd::Random(m, n + 3);
      Eigen::MatrixXd X = Eigen::MatrixXd::Constant(m, n + 2, 7.0);
      real_matrix_product(W, C.leftCols(n), X.leftCols(n));
      const Eigen::MatrixXd ref = W * C.leftCols(n);
      worst = std::max(worst, (X.leftCols(n) - ref).norm() / ref.norm());
      EXPECT_EQ(X(0, n), 7.0) << "wrote past its columns";
    }
  std::printf("  AVX2/FMA kernel in use: %s; worst relative difference from Eigen %.2e\n",
              real_matrix_product_uses_avx2() ? "yes" : "no (Eigen's product)", worst);
  EXPECT_LT(worst, 1e-15);
}

// Balancing: B0 = P R P^{-1} with P = diag(10^k) is R badly scaled (same eigenvalues). Balanced, the
// 1-norm comes back down, S B S^{-1} = B0 exactly, and the eigenvalues computed from the balanced matrix
// are R's to rounding — those computed from B0 directly are not (the point of balancing).
TEST(ExactPropagation, BalancingKeepsEigenvaluesAndShrinksTheNorm) {
  const Eigen::MatrixXd R = Eigen::MatrixXd::Random(12, 12);
  Eigen::MatrixXd B = R;
  for (int i = 0; i < 12; ++i) {
    B.row(i) *= std::pow(10.0, i - 6);
    B.col(i) /= std::pow(10.0, i - 6);
  }
  const Eigen::MatrixXd B0 = B;
  const Eigen::VectorXd S = balance_in_place(B);
  const double n0 = B0.cwiseAbs().colwise().sum().maxCoeff(), n1 = B.cwiseAbs().colwise().sum().maxCoeff();
  const Eigen::MatrixXd back = S.asDiagonal() * B * S.cwiseInverse().asDiagonal();
  auto eig = [](const Eigen::MatrixXd& A) {
    const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
    return std::vector<cd>(e.data(), e.data() + e.size());
  };
  const auto er = eig(R);
  const double scale = spectral_radius(er);
  const double d_balanced = root_set_distance(eig(B), er, scale), d_raw = root_set_distance(eig(B0), er, scale);
  std::printf("  1-norm %.3g -> %.3g; eigenvalues vs the unscaled matrix's: balanced %.2e, unbalanced %.2e\n", n0,
              n1, d_balanced, d_raw);
  EXPECT_LT(n1, n0 / 1e6);
  EXPECT_EQ((back - B0).cwiseAbs().maxCoeff(), 0.0);  // powers of two: exact
  EXPECT_LT(d_balanced, 1e-13);
}

// Many output times in blocks (threads, the two-level exponentials, the real form) against the state
// evaluated at each time alone, for a chain with and without friction (real and complex forms).
TEST(ExactPropagation, BlocksAgreeWithSingleTimes) {
  Body b1; b1.mass = 2; b1.A = 0.05; b1.C = 0.08; b1.com = 0.05; b1.next = 0.15; b1.spin = 200;
  b1.table = spheroid_file(1, 0.6); b1.scale = 0.04; b1.center = 0.05;
  Body b2; b2.mass = 1; b2.A = 0.02; b2.C = 0.035; b2.com = 0.04; b2.spin = 150;
  b2.table = spheroid_file(1, 0.7); b2.scale = 0.03; b2.center = 0.04;
  for (double friction : {0.0, 0.01}) {
    const ChainModel m = model_of(scene_text({b1, b2}, {{5.0, friction}}, 9.81, false, friction));
    const FirstOrderSystem f = build_first_order(m);
    ModalForm mf = modal_form(f, !m.has_friction(), kRealTolerance);
    ASSERT_TRUE(mf.usable);
    EXPECT_EQ(mf.real, friction == 0);
    Eigen::VectorXcd y0 = Eigen::VectorXcd::Random(f.dim());
    const long steps = 1000;
    const double h = 1e-3;
    for (int threads : {1, 2}) {
      Eigen::MatrixXcd Y(f.dim(), steps + 1);
      std::mutex mu;
      long seen = 0;
      modal_states(mf, y0, h, steps, [&](long j0, const auto& re, const auto& im) {
        std::lock_guard<std::mutex> lock(mu);
        for (long i = 0; i < re.cols(); ++i)
          for (long r = 0; r < re.rows(); ++r) Y(r, j0 + i) = cd(re(r, i), im(r, i));
        seen += re.cols();
      }, threads);
      EXPECT_EQ(seen, steps + 1);
      double worst = 0;
      for (long j : {0L, 1L, 31L, 32L, 33L, 500L, 999L, 1000L}) {
        const Eigen::VectorXcd y = modal_state_at(mf, y0, j * h);
        worst = std::max(worst, (Y.col(j) - y).norm() / y.norm());
      }
      std::printf("  friction %.2f (%s form), %d thread%s: blocks vs single times %.2e (|sigma| t up to %.0f)\n",
                  friction, mf.real ? "real" : "complex", threads, threads > 1 ? "s" : "", worst,
                  (mf.real ? mf.sigma.cwiseAbs().maxCoeff() : mf.mu.cwiseAbs().maxCoeff()) * steps * h);
      // The arguments sigma t are rounded differently (j h vs j0 h + r h): ~eps |sigma| t of phase.
      const double rho = mf.real ? mf.sigma.cwiseAbs().maxCoeff() : mf.mu.cwiseAbs().maxCoeff();
      EXPECT_LT(worst, 10 * 2.2e-16 * rho * steps * h);
    }
  }
}
