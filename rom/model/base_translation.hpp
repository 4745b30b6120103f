// A free chain carrying a partially filled tank (docs/free-chain.md, "Partially filled tanks"). The free chain of
// rigid bodies loses its base's translation X (the first joint's transverse displacement, m) through M − a aᵀ/m; a free
// surface's liquid has momentum of its own (its modes' t, docs/physics.md §2), so X is kept as the (n+1)-th coordinate
// of an extended chain — inertia M_ext with a, the total mass and the tanks' K over X, each mode's row w_l with its lever
// on X, no spin, stiffness or friction on X — and eliminated exactly through the chain's momentum, which no moment
// changes and which is taken as zero:
//   p_X = (M_eff,ext q̇)_X + Σ_l E_l w_lX w_l = 0   (state w_l = z_l + w_lᵀq̇),   i.e. Ẋ = base_rate(u̇, w).
// X itself enters nothing (only its rates do), so the chain keeps its state (s u, u̇, w) and its 2n + modes roots;
// Φ(σ) is the extended one's Schur complement on X.
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"
#include <complex>

namespace rc::rom {

// The extended chain (n + 1 coordinates, the last X; a fixed chain in form: no a aᵀ/m, no gravity) from the fixed-chain
// inertia M_fixed (bodies' block, with the tanks' K forms), a (Kononov's a_k), the total mass, and the free chain's
// bodies and modes (each mode's lever_base its weight on X).
ChainModel extend_with_base(const ChainModel& free, const Eigen::MatrixXd& M_fixed, const Eigen::VectorXd& a, double mass);

// Ẋ from the bodies' rates v and the fluid states w (the momentum p_X = 0 in the state of first_order_system.hpp).
std::complex<double> base_rate(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w);

// Ẋ from the bodies' rates v and the fluid coordinates z: p_X = (M_ext q̇)_X + Σ_l E_l w_lX z_l = 0.
std::complex<double> base_rate_from_z(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& z);

// The (n+1)-square matrix S of the extended chain reduced on X: S_uu − S_uX S_XX⁻¹ S_Xu.
Eigen::MatrixXcd reduce_on_base(const Eigen::MatrixXcd& S);

// d/dσ of reduce_on_base(Φ(σ)) from the extended Φ and Φ′.
Eigen::MatrixXcd reduced_derivative(const Eigen::MatrixXcd& Phi, const Eigen::MatrixXcd& dPhi);

// The extended first-order matrix (state (s q, q̇, w), q = (u, X)) reduced to the chain's (s u, u̇, w): X dropped, Ẋ
// from base_rate.
template <class Real>
Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic> reduce_first_order(
    const ChainModel& m, const Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic>& B_ext, Real s);

}  // namespace rc::rom
