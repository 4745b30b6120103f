// The damped modes of a viscous table taken as a Galerkin basis (docs/viscous.md, "Galerkin matrices").
//
// With the modes x_l (complex, in the block form of viscous_forms.hpp) as the columns of X, the Hermitian projection
// of the time-domain equations 𝓜ẋ = iAx + forcing (viscous_forms.hpp's pencil with e^{iλt}) on span X is
//   G ċ = i H c + Xᴴ(forcing),   G = Xᴴ𝓜X,  H = XᴴAX,
// and since A = −C + iEk K + (the real symmetric divergence blocks), the energy ½ cᴴGc of the reduced fluid changes
// at the rate −cᴴVc with the viscous dissipation form V = Ek XᴴKX = (H − Hᴴ)/(2i) exactly (C and the divergence
// blocks are real symmetric and so drop out of the anti-Hermitian part). For exact eigenvectors H = GΛ, which the
// table's dissipation_mismatch measures.
#pragma once

#include "viscous_forms.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

struct GalerkinMatrices {
  Eigen::MatrixXcd gram;      // G_lk = x̄_lᵀ𝓜x_k
  Eigen::MatrixXcd viscous;   // V_lk = Ek x̄_lᵀKx_k = ((H − Hᴴ)/(2i))_lk
  Eigen::MatrixXcd op;        // H_lk = x̄_lᵀAx_k
  Eigen::VectorXcd coupling;  // x̄_lᵀf (f real: the conjugate of the coupling fᵀx_l)
  Eigen::VectorXcd offset;    // x̄_lᵀg for a free surface's offset coupling g (viscous_forms.hpp); empty without one
};

// G, V, H, X̄ᵀf (and X̄ᵀg with a free surface) for the block vectors `modes` (damped modes made by viscous_modes_near with keep_block, or forced
// solutions), on the forms' communicator.
GalerkinMatrices project_on_modes(const ViscousForms& forms, const std::vector<Vec>& modes);

// max |V − (GΛ − ΛᴴG)/(2i)| / max |V|, Λ = diag(lambda): how far the viscous form is from the one the modes' own
// eigenvalues imply (0 for exact eigenvectors; the eigen-solver's residual otherwise).
double dissipation_mismatch(const GalerkinMatrices& g, const std::vector<std::complex<double>>& lambda);

}  // namespace rc::modes
