// ReducedTransfer (modes/viscous/reduced_transfer.hpp): lᵀ(σ𝓜 − 𝒜)⁻¹r of a small dense pencil by its pole–residue
// form, or by the Schur form where that form cannot be trusted, against a direct LU solve at the same σ.
#include "reduced_transfer.hpp"

#include "eigen_dense.hpp"
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
// Schur path is the transfer function to rounding.
TEST(ReducedTransfer, DefectivePencilFallsBackToTheSchurForm) {
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

// Two inputs (a partially filled tank's coupling and offset coupling): the matrix Lᵀ(σ𝓜 − 𝒜)⁻¹R, entry by entry, on
// both paths (a random pencil: pole–residue; a Jordan block: Schur) against direct solves.
TEST(ReducedTransfer, TwoInputsGiveTheTransferMatrix) {
  std::srand(5);
  const int m = 24;
  Eigen::MatrixXcd J = Eigen::MatrixXcd::Zero(m, m);
  for (int k = 0; k < m; ++k) J(k, k) = cd(0.4, 0.2);
  for (int k = 0; k + 1 < m; ++k) J(k, k + 1) = 1.0;
  const Eigen::MatrixXcd P = Eigen::MatrixXcd::Random(m, m) + 3.0 * Eigen::MatrixXcd::Identity(m, m);
  const Eigen::MatrixXcd L = Eigen::MatrixXcd::Random(m, 2), R = Eigen::MatrixXcd::Random(m, 2);
  const Eigen::MatrixXcd M = Eigen::MatrixXcd::Identity(m, m) + 0.1 * Eigen::MatrixXcd::Random(m, m);
  for (const Eigen::MatrixXcd& A : {Eigen::MatrixXcd(Eigen::MatrixXcd::Random(m, m)), Eigen::MatrixXcd(P * J * P.inverse())}) {
    const ReducedTransfer t(M, A, L, R);
    double worst = 0;
    for (const cd s : {cd(0.3, 0.0), cd(-1.2, 0.01), cd(2.5, -0.4)}) {
      const Eigen::MatrixXcd want = L.transpose() * (s * M - A).partialPivLu().solve(R);
      worst = std::max(worst, (t.matrix(s) - want).cwiseAbs().maxCoeff() / want.cwiseAbs().maxCoeff());
      EXPECT_EQ(t(s), t.matrix(s)(0, 0));
    }
    std::printf("two inputs, pole-residue form %s: worst entry error %.2e\n", t.pole_residue() ? "taken" : "refused",
                worst);
    EXPECT_LT(worst, 1e-10);
  }
}

// Told not to try the pole–residue form (the Krylov search, once a smaller basis's failed), a well-conditioned pencil
// takes the Schur path, and it is the transfer function to rounding too, at real σ as the search asks.
TEST(ReducedTransfer, SchurPathWhenThePolesAreNotTried) {
  std::srand(9);
  const int m = 60;
  const Eigen::MatrixXcd A = Eigen::MatrixXcd::Random(m, m);
  const Eigen::MatrixXcd M = Eigen::MatrixXcd::Identity(m, m) + 0.1 * Eigen::MatrixXcd::Random(m, m);
  const Eigen::MatrixXcd L = Eigen::MatrixXcd::Random(m, 2), R = Eigen::MatrixXcd::Random(m, 2);
  const ReducedTransfer poles(M, A, L, R), schur(M, A, L, R, false);
  double worst = 0, apart = 0;
  for (const cd s : {cd(0.3, 0.0), cd(-1.2, 0.0), cd(2.5, 0.0), cd(0.05, 1.0)}) {
    const Eigen::MatrixXcd want = L.transpose() * (s * M - A).partialPivLu().solve(R);
    worst = std::max(worst, (schur.matrix(s) - want).cwiseAbs().maxCoeff() / want.cwiseAbs().maxCoeff());
    apart = std::max(apart, (schur.matrix(s) - poles.matrix(s)).cwiseAbs().maxCoeff() / want.cwiseAbs().maxCoeff());
  }
  std::printf("Schur path against direct solves %.2e, against the pole-residue form %.2e\n", worst, apart);
  EXPECT_TRUE(poles.pole_residue());
  EXPECT_FALSE(schur.pole_residue());
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(apart, 1e-10);
}
