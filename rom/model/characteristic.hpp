// The matrix of the characteristic equation (22)/(29) of Kononov, with friction (Batyr (43)):
//   Phi(sigma) = M + diag(C_k w_k0)/sigma - i D/sigma - K/sigma^2
//                - diag( (sigma + w_k0) sum_l E_kl/(sigma + w_k0 - lambda_kl) + E_rem_k ),
// where -K/sigma^2 carries (a_k g - kappa_{k-1}^2 - kappa_k^2)/sigma^2 on the diagonal and
// kappa_k^2/sigma^2 off it. det Phi(sigma) = 0 at every root sigma (solutions e^{i sigma t}).
#pragma once

#include "chain_model.hpp"

#include <complex>

namespace rc::rom {

Eigen::MatrixXcd characteristic_matrix(const ChainModel& m, std::complex<double> sigma);

// dPhi/dsigma, term by term from characteristic_matrix:
//   -diag(C_k w_k0)/sigma^2 + i D/sigma^2 + 2K/sigma^3 + diag( sum_l E_kl lambda_kl/(sigma + w_k0 - lambda_kl)^2 ).
Eigen::MatrixXcd characteristic_derivative(const ChainModel& m, std::complex<double> sigma);

// Scaled residual of det Phi(sigma) = 0: smallest singular value of Phi over the sum of the
// 2-norms of its terms (a backward error: 0 at an exact root, O(1) far from one). Returns NaN
// where (22) is undefined: sigma = 0 (with 1/sigma terms present) or sigma at a pole
// sigma = lambda_kl - w_k0 (checked relative to `scale`, a typical |sigma|).
double characteristic_residual(const ChainModel& m, std::complex<double> sigma, double scale);

}  // namespace rc::rom
