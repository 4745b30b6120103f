// Coupling of one eigenpair (λ, p) to the body's tilt: E = 2ρ |(e1 × r, V)|² / ‖V‖² (docs/physics.md §2).
//
// Well-conditioned form. docs/physics.md §2 writes V with factors 1/λ and 1/D, D = 4 − λ². E does not depend on
// the scale of V, so we use Ṽ = λ D V, which has no divisions:
//   Ṽ_r ∝ λ² p_r + 2λ p/r,   Ṽ_φ ∝ −(2λ p_r + λ² p/r),   Ṽ_z ∝ −D p_z
// and, in terms of the assembled forms (m = 1, real p),
//   (e1 × r, Ṽ) = π [(λ² + 2λ) f1·p + D f2·p],
//   ‖Ṽ‖²        = 2π [λ²(λ² + 4) pᵀKh p + 4λ³ pᵀGc p + D² pᵀKz p],
// so E = 2 (e1 × r, Ṽ)² / ‖Ṽ‖² (up to the common sign of Ṽ, which E does not see). At the geostrophic end
// (λ → 0, where p_z = O(λ)) numerator and denominator both vanish like λ², with no cancellation.
#pragma once

#include "poincare_forms.hpp"

namespace rc::modes {

struct ModeCoupling {
  double E = 0;        // 2 a² / N² for ρ = 1
  double a = 0;        // (e1 × r, V) for V normalised to N² = ‖V‖² = 1
  double N2 = 1;       // normalisation of V (always 1 here)
};

// E, a, N² of an eigenpair from the form values of its eigenvector p (the formula above):
// f1p = f1·p, f2p = f2·p, kh = pᵀKh p, gc = pᵀGc p, kz = pᵀKz p. Throws if they are not finite.
ModeCoupling coupling_from_forms(double lambda, double f1p, double f2p, double kh, double gc, double kz);

class CouplingEvaluator {
 public:
  explicit CouplingEvaluator(const PoincareForms& forms);
  // Throws if the eigenvector is zero.
  ModeCoupling evaluate(double lambda, Vec p) const;

 private:
  const PoincareForms& forms_;
  PVec work_;
};

}  // namespace rc::modes
