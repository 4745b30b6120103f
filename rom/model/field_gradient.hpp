// A field that varies in space (the scene's [field] gradient G: f = G x, a potential's, docs/rom.md "A field that varies
// in space") in the linear chain (26): its potential −½ Σ_k ∫ xᵀG x dm to second order in the tilts, a stiffness.
// The linear model is axisymmetric, so G must be too: G = g_t (e_x e_xᵀ + e_y e_yᵀ) + g_z e_z e_zᵀ (e.g. an orbit's
// gravity gradient with the spin axis along the local vertical); the nonlinear chain takes any symmetric G.
#pragma once

#include "chain_model.hpp"
#include "scene.hpp"

namespace rc::rom {

// Whether G is symmetric about the spin axis e_z (to 1e-12 of its largest entry); a message naming what breaks it
// when it is not, empty when it is.
std::string gradient_asymmetry(const FieldSpec& field);

// Adds to the fixed chain's K, with O_k = Σ_{j<k} s_j n_j, n_k = (u_k, 1 − |u_k|²/2) and S_k = Σ_{j<k} s_j
// (m_k, c_k, A_k, C_k with the frozen liquid, as gravity takes them):
//   K_kk += m_k c_k g_z S_k + (A_k − C_k)(g_z − g_t)      (the body's centre's height and its inertia's orientation),
//   K_jj += m_k (S_k + c_k) g_z s_j,  K_ij −= m_k g_t s_i s_j,  K_jk = K_kj −= m_k c_k g_t s_j   (i, j < k).
void add_gradient_stiffness(const Scene& scene, ChainModel& model);

}  // namespace rc::rom
