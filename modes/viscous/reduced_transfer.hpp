// The transfer function t(σ) = lᵀ (σ𝓜 − 𝒜)⁻¹ r of a small dense pencil, at many σ: from the eigen-decomposition of
// 𝓜⁻¹𝒜 once (O(m³)), t(σ) = Σ_j ρ_j/(σ − p_j) costs O(m) per σ. Where the eigenvectors are too ill-conditioned for
// that (the pole–residue form disagrees with a direct solve by more than 1e-9 at a probe frequency), 𝓜⁻¹𝒜 is
// brought to upper Hessenberg form instead and each σ costs one Hessenberg solve (O(m²)). It is how the Krylov
// response reduction (krylov_response.hpp) scans a thousand candidate frequencies per step.
#pragma once

#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace rc::modes {

class ReducedTransfer {
 public:
  // `mass` must be invertible (an 𝓜-orthonormal basis's Gram matrix, or its bilinear counterpart).
  ReducedTransfer(const Eigen::MatrixXcd& mass, const Eigen::MatrixXcd& op, const Eigen::VectorXcd& left,
                  const Eigen::VectorXcd& right);
  std::complex<double> operator()(std::complex<double> sigma) const;
  bool pole_residue() const { return !poles_.empty(); }

 private:
  std::complex<double> hessenberg(std::complex<double> sigma) const;
  std::vector<std::complex<double>> poles_, residues_;  // empty: the Hessenberg path
  Eigen::MatrixXcd T_;        // upper Hessenberg: 𝓜⁻¹𝒜 = Q T Qᴴ
  Eigen::VectorXcd in_;       // Qᴴ 𝓜⁻¹ r
  Eigen::RowVectorXcd out_;   // lᵀ Q
};

}  // namespace rc::modes
