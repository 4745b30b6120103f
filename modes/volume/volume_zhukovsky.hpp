// Zhukovsky's inertia tensor of a 3-D cavity (Batyr (53)-(56) without the axial reduction; docs/volume.md §2):
// the potentials Δψ_k = 0, ∂ψ_k/∂n = (e_k × r)·n solve M ψ_k = g_k with g_k = ∫ (e_k × r)·∇q (e_k × r is
// solenoidal), and J_jk = ∫ ∇ψ_j·∇ψ_k = g_jᵀ M⁻¹ g_k, r from the fluid centroid. I_f − J_zh is the tensor sum rule.
#pragma once

#include "stiffness_solver.hpp"
#include "volume_forms.hpp"
#include "volume_velocity.hpp"

namespace rc::modes {

Tensor3 zhukovsky_tensor(const VolumeVelocity& V, const StiffnessSolver& M);

}  // namespace rc::modes
