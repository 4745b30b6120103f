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
// types took 247 s and made the clean build slower, docs/benchmarks.md "Build time"). Two lists, each compiled in its
// own file (eigen_dense_*.cpp) so that the build's cores share them. The complex SVD, the costliest of all (37-60 s for
// its one instantiation), goes through LAPACK instead (complex_svd.hpp).
#define RC_EIGEN_DENSE_FACTORISATIONS(X)  \
  X(Eigen::PartialPivLU<Eigen::MatrixXd>)  \
  X(Eigen::PartialPivLU<Eigen::MatrixXcd>) \
  X(Eigen::FullPivLU<Eigen::MatrixXcd>)    \
  X(Eigen::LLT<Eigen::MatrixXd>)

#define RC_EIGEN_DENSE_EIGENSOLVERS(X)                             \
  X(Eigen::EigenSolver<Eigen::MatrixXd>)                           \
  X(Eigen::RealSchur<Eigen::MatrixXd>)                             \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>)                \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>)               \
  X(Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>)     \
  X(Eigen::ComplexEigenSolver<Eigen::MatrixXcd>)                   \
  X(Eigen::ComplexSchur<Eigen::MatrixXcd>)

// A class's explicit instantiation leaves out its member templates (C++ [temp.explicit]), and each solver's compute()
// is one: template <typename InputType> compute(const EigenBase<InputType>&, ...), called by the constructor that
// takes a matrix. So each file that constructed a solver from a matrix still compiled the whole algorithm (its
// Hessenberg or tridiagonal reduction and QR iteration) of its own: 6-9 s a solver at -O3 (measured 2026-12-01:
// ComplexEigenSolver 7.6 s -> 1.4 s, EigenSolver 10.5 s -> 1.3 s for a file with one solver, once this list
// declares compute for an input of the solver's own matrix type). A solver given an expression (a block, a product)
// still compiles compute for that expression where it is used: pass it a matrix.
#define RC_EIGEN_DENSE_COMPUTES(X)                                                   \
  X(Eigen::EigenSolver<Eigen::MatrixXd>, Eigen::MatrixXd, bool)                     \
  X(Eigen::RealSchur<Eigen::MatrixXd>, Eigen::MatrixXd, bool)                       \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>, Eigen::MatrixXd, int)           \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>, Eigen::MatrixXcd, int)         \
  X(Eigen::ComplexEigenSolver<Eigen::MatrixXcd>, Eigen::MatrixXcd, bool)            \
  X(Eigen::ComplexSchur<Eigen::MatrixXcd>, Eigen::MatrixXcd, bool)

#ifndef RC_EIGEN_DENSE_DEFINITIONS
#define RC_EIGEN_DENSE_DECLARE(T) extern template class T;
RC_EIGEN_DENSE_FACTORISATIONS(RC_EIGEN_DENSE_DECLARE)
RC_EIGEN_DENSE_EIGENSOLVERS(RC_EIGEN_DENSE_DECLARE)
#undef RC_EIGEN_DENSE_DECLARE
#define RC_EIGEN_DENSE_DECLARE_COMPUTE(Solver, Matrix, Option) \
  extern template Solver& Solver::compute<Matrix>(const Eigen::EigenBase<Matrix>&, Option);
RC_EIGEN_DENSE_COMPUTES(RC_EIGEN_DENSE_DECLARE_COMPUTE)
#undef RC_EIGEN_DENSE_DECLARE_COMPUTE
#endif
