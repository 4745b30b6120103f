// The transfer function t(σ) = Lᵀ (σ𝓜 − 𝒜)⁻¹ R of a small dense pencil, at many σ: from the eigen-decomposition of
// 𝓜⁻¹𝒜 once (O(m³)), t(σ) = Σ_j ρ_j/(σ − p_j) costs O(m) per σ and entry. Where the eigenvectors are too
// ill-conditioned for that (the pole–residue form disagrees with a direct solve by more than 1e-9 at a probe
// frequency), 𝓜⁻¹𝒜 is brought to upper Hessenberg form instead and each σ costs one Hessenberg solve (O(m²)). It is
// how the Krylov response reduction (krylov_response.hpp) scans a thousand candidate frequencies per step.
// L and R have one column per input (a partially filled tank has two: the coupling and the offset coupling), and t
// is then the matrix of every pair's transfer function.
#pragma once

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

class ReducedTransfer {
 public:
  // `mass` must be invertible (an 𝓜-orthonormal basis's Gram matrix, or its bilinear counterpart).
  ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op, const Eigen::MatrixXcd& left,
                  const Eigen::MatrixXcd& right);
  // Lᵀ (σ𝓜 − 𝒜)⁻¹ R: columns of L × columns of R.
  Eigen::MatrixXcd matrix(std::complex<double> sigma) const;
  // Its first entry (one input).
  std::complex<double> operator()(std::complex<double> sigma) const { return matrix(sigma)(0, 0); }
  bool pole_residue() const { return !poles_.empty(); }

 private:
  Eigen::MatrixXcd hessenberg(std::complex<double> sigma) const;
  std::vector<std::complex<double>> poles_;  // empty: the Hessenberg path
  Eigen::MatrixXcd out_poles_;  // Lᵀ V (V the eigenvectors)
  Eigen::MatrixXcd in_poles_;   // V⁻¹ 𝓜⁻¹ R
  Eigen::MatrixXcd T_;          // upper Hessenberg: 𝓜⁻¹𝒜 = Q T Qᴴ
  Eigen::MatrixXcd in_;         // Qᴴ 𝓜⁻¹ R
  Eigen::MatrixXcd out_;        // Lᵀ Q
};

}  // namespace rc::modes
