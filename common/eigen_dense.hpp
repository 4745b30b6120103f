// Eigen's dense module with its decompositions compiled once (common/eigen_dense_*.cpp), not in every file that uses
// them: each decomposition of the matrix types we use is declared an explicit instantiation here, so a file that
// includes this header instead of <Eigen/Dense> calls the one compiled copy. Measured 2026-11-29 on this 2-core
// machine (-O3, the build's per-file times): modes/viscous/rational_fit.cpp 74 s -> 17 s,
// freesurface/free_surface_radial.cpp 32 s -> 4 s, partial_fill_cylinder.cpp 36 s -> 25 s (docs/benchmarks.md,
// "Build time"). A decomposition of another type still compiles in the file that uses it, as before.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

// Three lists, each compiled in its own file (eigen_dense_*.cpp) so that the build's cores share them.
#define RC_EIGEN_DENSE_FACTORISATIONS(X)                                              \
  X(Eigen::PartialPivLU<Eigen::MatrixXd>)                                             \
  X(Eigen::PartialPivLU<Eigen::MatrixXcd>)                                            \
  X(Eigen::FullPivLU<Eigen::MatrixXd>)                                                \
  X(Eigen::FullPivLU<Eigen::MatrixXcd>)                                               \
  X(Eigen::LLT<Eigen::MatrixXd>)                                                      \
  X(Eigen::LLT<Eigen::MatrixXcd>)                                                     \
  X(Eigen::LDLT<Eigen::MatrixXd>)                                                     \
  X(Eigen::HouseholderQR<Eigen::MatrixXd>)                                            \
  X(Eigen::HouseholderQR<Eigen::MatrixXcd>)                                           \
  X(Eigen::ColPivHouseholderQR<Eigen::MatrixXd>)                                      \
  X(Eigen::ColPivHouseholderQR<Eigen::MatrixXcd>)                                     \
  X(Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXcd>)

#define RC_EIGEN_DENSE_SVDS(X)                                                        \
  X(Eigen::JacobiSVD<Eigen::MatrixXd>)                                                \
  X(Eigen::JacobiSVD<Eigen::MatrixXcd>)                                               \
  X(Eigen::JacobiSVD<Eigen::Matrix3cd>)                                               \
  X(Eigen::BDCSVD<Eigen::MatrixXd>)                                                   \
  X(Eigen::BDCSVD<Eigen::MatrixXcd>)

#define RC_EIGEN_DENSE_EIGENSOLVERS(X)                                                \
  X(Eigen::EigenSolver<Eigen::MatrixXd>)                                              \
  X(Eigen::EigenSolver<Eigen::Matrix3d>)                                              \
  X(Eigen::GeneralizedEigenSolver<Eigen::MatrixXd>)                                   \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>)                                   \
  X(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>)                                  \
  X(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>)                                   \
  X(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd>)                                  \
  X(Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>)                        \
  X(Eigen::ComplexEigenSolver<Eigen::MatrixXcd>)                                      \
  X(Eigen::ComplexSchur<Eigen::MatrixXcd>)                                            \
  X(Eigen::RealSchur<Eigen::MatrixXd>)                                                \
  X(Eigen::RealQZ<Eigen::MatrixXd>)                                                   \
  X(Eigen::HessenbergDecomposition<Eigen::MatrixXd>)                                  \
  X(Eigen::HessenbergDecomposition<Eigen::MatrixXcd>)                                 \
  X(Eigen::Tridiagonalization<Eigen::MatrixXd>)                                       \
  X(Eigen::Tridiagonalization<Eigen::MatrixXcd>)

#ifndef RC_EIGEN_DENSE_DEFINITIONS
#define RC_EIGEN_DENSE_DECLARE(T) extern template class T;
RC_EIGEN_DENSE_FACTORISATIONS(RC_EIGEN_DENSE_DECLARE)
RC_EIGEN_DENSE_SVDS(RC_EIGEN_DENSE_DECLARE)
RC_EIGEN_DENSE_EIGENSOLVERS(RC_EIGEN_DENSE_DECLARE)
#undef RC_EIGEN_DENSE_DECLARE
#endif
