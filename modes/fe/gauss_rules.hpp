// One-dimensional Gauss rules on [-1, 1]: Gauss–Legendre (quadrature) and Gauss–Lobatto–Legendre points
// (well-conditioned interpolation nodes of high-order line elements, line_space.hpp).
#pragma once

#include <vector>

namespace rc::modes {

// n-point Gauss–Legendre nodes (ascending) and weights; exact for polynomials of degree 2n − 1.
// Newton on P_n from Chebyshev-like guesses: accurate to rounding for n <= 200.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w);

// The n + 1 Gauss–Lobatto–Legendre points (ascending, −1 and 1 included): the roots of (1 − x²) P_n′(x).
std::vector<double> gauss_lobatto_points(int n);

}  // namespace rc::modes
