// The one compiled copy of each of eigen_dense.hpp's factorisations (the other lists: eigen_dense_*.cpp).
#define RC_EIGEN_DENSE_DEFINITIONS
#include "eigen_dense.hpp"

#define RC_EIGEN_DENSE_DEFINE(T) template class T;
RC_EIGEN_DENSE_FACTORISATIONS(RC_EIGEN_DENSE_DEFINE)
