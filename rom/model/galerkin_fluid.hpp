// A cavity's kept modes as a Galerkin basis of its fluid (docs/rom.md, "Galerkin tanks"; docs/viscous.md, "Galerkin
// matrices"): the reduced fluid that keeps an energy and dissipates it at the viscous rate, in the chain's modal form.
//
// With the kept rows' modes x_l, their Gram matrix G = X̄ᵀ𝓜X and viscous form V = Ek X̄ᵀKX (the table's /galerkin), and
// their couplings f_l = fᵀx_l = √(2/π)(a_l + i a_imag,l), the Hermitian (Galerkin) projection of the forced fluid on
// span X has the same eigenvalues λ_l (the span is invariant) but the residues
//   Ẽ_l = π f_l g_l,   g = G⁻¹ f̄,
// instead of the modal π f_l² (they agree when the modes are orthogonal: every ideal table). In the chain's fluid
// coordinates z_l (Kononov (26), docs/rom.md "Equations", with E_l → Ẽ_l) the fluid's kinetic energy relative to its
// cavity and its viscous dissipation are
//   ½ zᴴ 𝔈 z,  𝔈 = π diag(ḡ) G diag(g),      zᴴ 𝔇 z,  𝔇 = π diag(ḡ) V diag(g),
// with 𝔈 1 = conj(Ẽ) (so Σ Ẽ = π f̄ᵀG⁻¹f̄ is real, the share of A_f − J_zh that the kept span carries) and, for exact
// modes, 𝔇 = (𝔈Λ − Λᴴ𝔈)/(2i).
#pragma once

#include "mode_table.hpp"

#include "eigen_dense.hpp"

#include <vector>

namespace rc::rom {

struct GalerkinFluid {
  Eigen::VectorXcd residue;     // Ẽ_l (table units: ρ = 1, L = 1)
  Eigen::MatrixXcd energy;      // 𝔈 (Hermitian positive definite)
  Eigen::MatrixXcd dissipation; // 𝔇 (Hermitian positive semi-definite; table units, ω0 = 1)
};

// For the table rows `rows` (the kept modes, in the chain's order). An ideal table's modes are orthogonal (G = I,
// V = 0): its Galerkin fluid is its modal one. A Galerkin response table (cavity-modes response --galerkin) holds
// Ritz vectors with their couplings f_l; its E are these Ẽ already when every row is kept. Throws
// std::runtime_error with the reason when the table has no Galerkin matrices (a viscous table made before them, or a
// rational fit, whose poles are not modes) or the kept modes' Gram matrix is singular.
GalerkinFluid galerkin_fluid(const rc::ModeTable& t, const std::vector<int>& rows);

}  // namespace rc::rom
