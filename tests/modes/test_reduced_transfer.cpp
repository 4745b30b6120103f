// ReducedTransfer (modes/viscous/reduced_transfer.hpp): lᵀ(σ𝓜 − 𝒜)⁻¹r of a small dense pencil by its pole–residue
// form, or by a Hessenberg solve where that form cannot be trusted, against a direct LU solve at the same σ.
#include "reduced_transfer.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>

using namespace rc::modes;
using cd = std::complex<double>;

namespace {

cd direct(const Eigen::MatrixXcd& M, const Eigen::MatrixXcd& A, const Eigen::VectorXcd& l, const Eigen::VectorXcd& r,
          cd s) {
  const Eigen::MatrixXcd S = s * M - A;
  return (l.transpose() * S.partialPivLu().solve(r))(0);
}

double worst_error(const ReducedTransfer& t, const Eigen::MatrixXcd& M, const Eigen::MatrixXcd& A,
                   const Eigen::VectorXcd& l, const Eigen::VectorXcd& r) {
  double worst = 0;
  for (const cd s : {cd(0.3, 0.0), cd(-1.2, 0.01), cd(2.5, -0.4), cd(0.05, 1.0)}) {
    const cd want = direct(M, A, l, r, s);
    worst = std::max(worst, std::abs(t(s) - want) / std::abs(want));
  }
  return worst;
}

}  // namespace

// A random well-conditioned pencil (𝓜 near the identity): the pole–residue form is taken, and it is the transfer
// function to rounding.
TEST(ReducedTransfer, PoleResidueFormIsTheTransferFunction) {
  std::srand(7);
  const int m = 40;
  const Eigen::MatrixXcd A = Eigen::MatrixXcd::Random(m, m);
  const Eigen::MatrixXcd M = Eigen::MatrixXcd::Identity(m, m) + 0.1 * Eigen::MatrixXcd::Random(m, m);
  const Eigen::VectorXcd l = Eigen::VectorXcd::Random(m), r = Eigen::VectorXcd::Random(m);
  const ReducedTransfer t(M, A, l, r);
  const double err = worst_error(t, M, A, l, r);
  std::printf("pole-residue form %s, worst relative error %.2e\n", t.pole_residue() ? "taken" : "refused", err);
  EXPECT_TRUE(t.pole_residue());
  EXPECT_LT(err, 1e-11);
}

// A defective pencil (a Jordan block: its eigenvectors are parallel): the pole–residue form is refused and the
// Hessenberg path is the transfer function to rounding.
TEST(ReducedTransfer, DefectivePencilFallsBackToHessenberg) {
  std::srand(11);
  const int m = 12;
  Eigen::MatrixXcd J = Eigen::MatrixXcd::Zero(m, m);
  for (int k = 0; k < m; ++k) J(k, k) = cd(0.7, 0.1);
  for (int k = 0; k + 1 < m; ++k) J(k, k + 1) = 1.0;
  const Eigen::MatrixXcd P = Eigen::MatrixXcd::Random(m, m) + 3.0 * Eigen::MatrixXcd::Identity(m, m);
  const Eigen::MatrixXcd A = P * J * P.inverse();
  const Eigen::MatrixXcd M = Eigen::MatrixXcd::Identity(m, m);
  const Eigen::VectorXcd l = Eigen::VectorXcd::Random(m), r = Eigen::VectorXcd::Random(m);
  const ReducedTransfer t(M, A, l, r);
  const double err = worst_error(t, M, A, l, r);
  std::printf("pole-residue form %s, worst relative error %.2e\n", t.pole_residue() ? "taken" : "refused", err);
  EXPECT_FALSE(t.pole_residue());
  EXPECT_LT(err, 1e-10);
}
