// The transfer function t(σ) = Lᵀ (σ𝓜 − 𝒜)⁻¹ R of a small dense pencil, at many σ: from the eigen-decomposition of
// 𝓜⁻¹𝒜 once (O(m³)), t(σ) = Σ_j ρ_j/(σ − p_j) costs O(m) per σ and entry. Where the eigenvectors are too
// ill-conditioned for that (the pole–residue form disagrees with a direct solve by more than 1e-9 at a probe
// frequency), or the caller knows they were for the pencil it grew from, the complex Schur form 𝓜⁻¹𝒜 = Z T Zᴴ is
// taken instead and each σ costs one triangular solve (O(m²), backward stable). It is how the Krylov response
// reduction (krylov_response.hpp) scans a thousand candidate frequencies per step.
// L and R have one column per input (a partially filled tank has two: the coupling and the offset coupling), and t
// is then the matrix of every pair's transfer function.
#pragma once

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

class ReducedTransfer {
 public:
  // `mass` must be invertible (an 𝓜-orthonormal basis's Gram matrix, or its bilinear counterpart). With
  // try_poles = false the Schur form is taken without trying the eigen-decomposition first.
  ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op, const Eigen::MatrixXcd& left,
                  const Eigen::MatrixXcd& right, bool try_poles = true);
  // Lᵀ (σ𝓜 − 𝒜)⁻¹ R: columns of L × columns of R.
  Eigen::MatrixXcd matrix(std::complex<double> sigma) const;
  // Its first entry (one input).
  std::complex<double> operator()(std::complex<double> sigma) const { return matrix(sigma)(0, 0); }
  bool pole_residue() const { return !poles_.empty(); }

 private:
  Eigen::MatrixXcd schur(std::complex<double> sigma) const;
  std::vector<std::complex<double>> poles_;  // empty: the Schur path
  Eigen::MatrixXcd out_poles_;  // Lᵀ V (V the eigenvectors)
  Eigen::MatrixXcd in_poles_;   // V⁻¹ 𝓜⁻¹ R
  // Row-major: the back substitution takes each row's dot product with the solution, reading T once per σ.
  Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> T_;  // 𝓜⁻¹𝒜 = Z T Zᴴ
  Eigen::MatrixXcd in_;         // Zᴴ 𝓜⁻¹ R
  Eigen::MatrixXcd out_;        // Lᵀ Z
};

}  // namespace rc::modes
