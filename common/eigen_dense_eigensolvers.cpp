// The one compiled copy of each of eigen_dense.hpp's eigensolvers (the other lists: eigen_dense_*.cpp).
#define RC_EIGEN_DENSE_DEFINITIONS
#include "eigen_dense.hpp"

#define RC_EIGEN_DENSE_DEFINE(T) template class T;
RC_EIGEN_DENSE_EIGENSOLVERS(RC_EIGEN_DENSE_DEFINE)
#define RC_EIGEN_DENSE_DEFINE_COMPUTE(Solver, Matrix, Option) \
  template Solver& Solver::compute<Matrix>(const Eigen::EigenBase<Matrix>&, Option);
RC_EIGEN_DENSE_COMPUTES(RC_EIGEN_DENSE_DEFINE_COMPUTE)
