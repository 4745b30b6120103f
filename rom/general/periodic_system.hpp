// The chain at two spins (docs/rom.md, "Bodies at different spins"): a body without axial symmetry or with tanks that
// turns against the frame F at θ̇_k = ω_k − ω0 carries its anisotropy Δ_k, its tanks' couplings c, c_left and its
// geostrophic weight G_k round with it, θ_k = θ̇_k t. Seen from F they are R(θ_k)Δ_kR(θ_k)ᵀ, R c, R G Rᵀ, and turning
// adds, to the constant chain of general_system.hpp written with them (Lagrange's equations of ½δωᵀΔ(t)δω, δω = J q̇ − ω0 q
// in F's axes whatever the body's spin; the moment −(ḣ + ω0 e_z × h) with h = 2 Re(z c) − G δω in F's axes; the
// mode's ż = iλ z − c_left·δω̇ in the body's axes, λ = ω_k λ_table):
//   body k's q-equations:  −2θ̇ JΔ(t) q̇ − 2ω0θ̇ Δ(t) q + Pᵀ[θ̇ J h_modes − θ̇(JG − GJ)δω + W Ĉ θ̇J δω],
//   each mode of body k:   ż gains θ̇ c_left·(J δω)      (J = e_z ×, h_modes = Σ 2 Re(z c)).
// B(t + T) = B(t), T = 2π/|θ̇|; floquet.hpp finds the roots.
#pragma once

#include "general_chain.hpp"
#include "general_system.hpp"

#include "eigen_dense.hpp"

namespace rc::rom {

// The chain as F sees it at time t, frozen: each body's anisotropy (in M and K), its tanks' coupling vectors and its
// geostrophic weight turned by θ_k = (ω_k − ω0) t about the vertical.
GeneralChain turned_chain(const GeneralChain& g, double t);

// B(t) of y' = B(t) y in general_system.hpp's state (s q, Q̇, Z), q carried as s q with the s given. Throws
// std::runtime_error when it is not finite.
Eigen::MatrixXd periodic_matrix(const GeneralChain& g, double t, double s);

// The same B(t) with the input of an external generalised force at t (y' = B y + input F; the input turns with the
// bodies' anisotropy through the effective inertia).
GeneralSystem periodic_system(const GeneralChain& g, double t, double s);

}  // namespace rc::rom
