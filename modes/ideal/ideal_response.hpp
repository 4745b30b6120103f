// The ideal fluid's moment response at complex frequencies by direct forced solves, no modes
// (docs/viscous.md, "Response function"; the ideal counterpart of viscous/viscous_response.hpp):
//   R(σ) = Σ_l E_l / (σ − λ_l) = ∫ dμ(λ) / (σ − λ),
// the Stieltjes transform of the coupling's spectral measure μ = Σ E_l δ(λ − λ_l) (docs/modes.md, "Spectral
// survey"), summed over EVERY discrete eigenpair of the mesh's Poincaré problem without computing one.
//
// With A = P_H S the self-adjoint operator of the discrete problem on solenoidal fields and u = e1 × r in the
// quadrature-point velocity space (velocity_space.hpp), R(σ) = −π uᵀΩ (A − σ)⁻¹ u. The forced problem
// (shift_invert_survey.hpp) gives, with y = (S − σ)⁻¹ u, g = Gᵀ Ω y and c = σ(σ² − 4),
//   R(σ) = −π [ uᵀΩ y + c gᵀ Q(σ)⁻¹ g ],   Q(σ) = σ² M + 2σ Gc − 4 Kz,
// all bilinear (no conjugation), so it holds for complex σ. y is explicit: (S − σ)⁻¹ is [[−σ, 2], [2, −σ]]/(σ² − 4)
// on (a, b) and −1/σ on c, so uᵀΩy and g are fixed combinations of three real quantities computed once. The
// complex symmetric Q(σ)p = g is solved in the real symmetric block form
//   [[Re Q, Im Q], [Im Q, −Re Q]] [Re p; −Im p] = [Re g; Im g]   (MUMPS LDLᵀ, one factorisation per σ).
#pragma once

#include "poincare_forms.hpp"
#include "velocity_space.hpp"

#include <complex>
#include <vector>

namespace rc::modes {

// σ must avoid {0, ±2} (where (S − σ) is singular) and the discrete spectrum (Q(σ) singular): a real σ inside
// (−2, 2) is refused with std::invalid_argument, a failed factorisation throws std::runtime_error.
std::vector<std::complex<double>> ideal_response(const VelocitySpace& V, const PoincareForms& forms,
                                                 const std::vector<std::complex<double>>& sigmas);

}  // namespace rc::modes
