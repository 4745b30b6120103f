// Zhukovsky's transverse inertia of the fluid (Batyr, (53)-(56); docs/physics.md §2): the potential ψ = χ sin φ
// with Δψ = 0, ∂ψ/∂n = (e1 × r)·n solves, in the meridian form,
//   ∫∫ (χ_r q_r + χ q / r² + χ_z q_z) r dr dz = ∫∫ (e1 × r)·∇q  (= f1 − f2, see poincare_forms.hpp),
// and J_zh = π ∫∫ (χ_r² + χ²/r² + χ_z²) r dr dz = π χᵀ M χ = π bᵀ χ.
#pragma once

#include "poincare_forms.hpp"
#include "stiffness_solver.hpp"

namespace rc::modes {

struct ZhukovskyResult {
  double J_zh = 0;
  double relative_residual = 0;  // ‖M χ − b‖ / ‖b‖ of the solve (0 when b = 0)
};

ZhukovskyResult zhukovsky_inertia(const PoincareForms& forms, const StiffnessSolver& solver);

}  // namespace rc::modes
