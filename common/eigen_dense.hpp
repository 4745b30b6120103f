// Eigen's dense module with its decompositions compiled once (common/eigen_dense_*.cpp), not in every file that uses
// them: each decomposition of the matrix types we use is declared an explicit instantiation here, so a file that
// includes this header instead of <Eigen/Dense> calls the one compiled copy (modes/viscous/rational_fit.cpp: 74 s ->
// 17 s at -O3). A decomposition of another type still compiles in the file that uses it, as before.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

// Only the decompositions that several files use and that cost seconds to compile are listed: an explicit
// instantiation compiles every member, so a type used once costs more here than where it is used (measured 2026-11-29,
// each alone at -O3: BDCSVD<MatrixXcd> 60 s, SelfAdjointEigenSolver 12-14 s, PartialPivLU 7 s; the first list of 33
// types took 247 s and made the clean build slower, docs/benchmarks.md "Build time"). Three lists, each compiled in its
// own file (eigen_dense_*.cpp) so that the build's cores share them.
#define RC_EIGEN_DENSE_FACTORISATIONS(X)  \
  X(Eigen::PartialPivLU<Eigen::MatrixXd>)  \
  X(Eigen::PartialPivLU<Eigen::MatrixXcd>) \
  X(Eigen::FullPivLU<Eigen::MatrixXcd>)    \
  X(Eigen::LLT<Eigen::MatrixXd>)

#define RC_EIGEN_DENSE_SVDS(X) X(Eigen::BDCSVD<Eigen::MatrixXcd>)

#define RC_EIGEN_DENSE_EIGENSOLVERS(X)                             \
  X(Eigen::EigenSolver<Eigen::MatrixXd>)                           \
  X(Eigen::RealSchur<Eigen::MatrixXd>)                             \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>)                \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>)               \
  X(Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>)     \
  X(Eigen::ComplexEigenSolver<Eigen::MatrixXcd>)                   \
  X(Eigen::ComplexSchur<Eigen::MatrixXcd>)

#ifndef RC_EIGEN_DENSE_DEFINITIONS
#define RC_EIGEN_DENSE_DECLARE(T) extern template class T;
RC_EIGEN_DENSE_FACTORISATIONS(RC_EIGEN_DENSE_DECLARE)
RC_EIGEN_DENSE_SVDS(RC_EIGEN_DENSE_DECLARE)
RC_EIGEN_DENSE_EIGENSOLVERS(RC_EIGEN_DENSE_DECLARE)
#undef RC_EIGEN_DENSE_DECLARE
#endif
