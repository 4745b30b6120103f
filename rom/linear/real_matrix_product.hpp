// X = W C for real column-major matrices: the one product per block of output times that exact
// propagation spends most of its time in (exact_propagation.cpp). The build targets baseline x86-64
// (SSE2), where Eigen's product runs at a third of what the AVX2/FMA units of current CPUs do; this
// product checks the CPU at run time and uses a small AVX2/FMA kernel when it can, Eigen otherwise.
// The kernel is a plain function compiled for AVX2 by a target attribute — no Eigen code is compiled
// twice with different instruction sets (which would break the one-definition rule).
#pragma once

#include "eigen_dense.hpp"

namespace rc::rom {

// X (rows of W x cols of C) = W C. X must already have that size and not alias W or C.
void real_matrix_product(const Eigen::MatrixXd& W, const Eigen::Ref<const Eigen::MatrixXd>& C,
                         Eigen::Ref<Eigen::MatrixXd> X);

// True when real_matrix_product uses the AVX2/FMA kernel on this CPU.
bool real_matrix_product_uses_avx2();

}  // namespace rc::rom
