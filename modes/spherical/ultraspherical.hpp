// The ultraspherical (Olver–Townsend) spectral method's sparse operators on [-1, 1]: a function is its Chebyshev
// coefficients (f = Σ a_k T_k), and the k-th derivative lands in the coefficients of the Gegenbauer polynomials
// C^(k), where it is banded; conversions S_λ: C^(λ) → C^(λ+1) and multiplication by x are banded too. An equation
// of order k is written in C^(k): every term converted up to it, so that the whole operator is sparse and
// well conditioned (S. Olver and A. Townsend, "A fast and well-conditioned spectral method", SIAM Review 55, 2013,
// §2; the recurrences are DLMF 18.9.7, 18.9.8 and 18.9.19).
//
// Every operator here maps the coefficients of degrees 0 … n−1 to those of degrees 0 … n−1 (square n × n); products
// that raise the degree (x^j) lose their top coefficients, which is the tau method's truncation: callers build at a
// few degrees above what they keep (UltrasphericalOperators::padding) and cut.
#pragma once

#include <Eigen/SparseCore>

namespace rc::modes::spherical {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// d^k/dx^k from Chebyshev T coefficients to C^(k) coefficients (k ≥ 1): T_j^(k) = 2^(k−1) (k−1)! j C^(k)_{j−k}.
SparseMatrix derivative(int n, int k);

// S_λ: C^(λ) → C^(λ+1) for λ ≥ 1, and S_0: T → C^(1).
SparseMatrix conversion(int n, int lambda);

// The conversion from C^(from) to C^(to) (from ≤ to; from = 0 is Chebyshev T): S_{to−1} ⋯ S_from.
SparseMatrix conversion(int n, int from, int to);

// Multiplication by x in C^(λ) (λ = 0: Chebyshev T).
SparseMatrix multiply_by_x(int n, int lambda);

// Multiplication by r^power in C^(λ), where r = scale x + shift maps [-1, 1] onto the radial interval.
SparseMatrix multiply_by_r(int n, int lambda, double scale, double shift, int power);

}  // namespace rc::modes::spherical
