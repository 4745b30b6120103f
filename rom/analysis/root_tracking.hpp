// Root tracking for stability maps (`chain-rom sweep`): the roots of a map point from those of its neighbour,
// instead of a new eigenproblem at every point (docs/rom.md, "Stability maps", root tracking).
//
// The roots of the chain are the zeros of the polynomial of degree 2n + (kept modes)
//   f(sigma) = sigma^{2n} prod_l (sigma - p_l) det Phi(sigma),   p_l = lambda_kl - omega_k0,
// Phi being the matrix of the characteristic equation (22)/(29) of Kononov (characteristic.hpp). Its
// logarithmic derivative costs O(modes + n^3) per point sigma:
//   f'/f = 2n/sigma + sum_l 1/(sigma - p_l) + tr(Phi^{-1} Phi').
// Aberth–Ehrlich's simultaneous iteration (O. Aberth, "Iteration methods for finding all zeros of a
// polynomial simultaneously", Math. Comp. 1973; D. A. Bini, "Numerical computation of polynomial zeros by
// means of Aberth's method", Numer. Algorithms 1996), Gauss–Seidel style,
//   z_j <- z_j - N_j / (1 - N_j sum_{i != j} 1/(z_j - z_i)),   N_j = f(z_j)/f'(z_j),
// started from the neighbouring point's roots, moves every approximation to its own zero; one whose Newton
// correction is already below the tolerance is taken as it is (most fluid roots hardly move between points).
//
// A tracked set is accepted only if it is provably the whole set of roots: every approximation converged
// (its correction below the tolerance), all of them pairwise apart by far more than the tolerance (so they sit
// on deg f distinct zeros), and their sum equals the trace of the first-order matrix of (26), -i tr B (which
// ties f to the eigenproblem the rest of chain-rom solves). Otherwise the caller falls back to the eigen-solver.
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"
#include <complex>
#include <string>
#include <vector>

namespace rc::rom {

// f'/f of the chain's characteristic polynomial, with the model's coefficients laid out for a fast evaluation.
class CharacteristicLogDerivative {
 public:
  // Chains of more bodies than this are not tracked (the n x n solve is on the stack).
  static constexpr int kMaxBodies = 8;
  explicit CharacteristicLogDerivative(const ChainModel& m);
  // f'/f at sigma into `value`; `root` where (22) is exactly singular (sigma is a root), `undefined` at sigma = 0
  // (or on two coincident poles of one body).
  enum class Result { value, root, undefined };
  Result eval(std::complex<double> sigma, std::complex<double>& value) const;
  int degree() const { return 2 * n_ + static_cast<int>(pole_.size()); }

 private:
  int n_ = 0;
  Eigen::MatrixXd M_, D_;
  Eigen::MatrixXcd K_;  // with the Magnus moments complex (complex_stiffness)
  std::vector<double> G_;
  std::vector<std::complex<double>> E_rem_;
  std::vector<int> first_mode_;           // modes of body k: [first_mode_[k], first_mode_[k + 1])
  std::vector<std::complex<double>> pole_, E_, E_lambda_;
  std::vector<double> omega_;             // omega_k0, per body
};

struct TrackedRoots {
  Eigen::VectorXcd sigma;  // the roots (rad/s), in the order of the start values they were tracked from
  bool ok = false;         // accepted (see the file comment); else `why` says what failed
  int sweeps = 0;          // Aberth sweeps over the unconverged approximations
  std::string why;
};

// Tracks the roots of m from `start` (the roots at a neighbouring point, or a prediction from two of them).
// `radius`: the size of the chain's oscillating roots (the verdict's radius), which sets the absolute
// tolerance 1e-13 * radius (relative 1e-14 for larger roots).
TrackedRoots track_roots(const ChainModel& m, const Eigen::VectorXcd& start, double radius);

}  // namespace rc::rom
