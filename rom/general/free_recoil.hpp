// A free chain with partially filled 3-D tanks (docs/volume.md §8, "The free chain"). A free surface gives the liquid's
// modes momentum, so the body recoils: the base's translation X (the first joint's displacement in F) is kept as one
// more body of an extended chain and eliminated through the chain's momentum, as docs/free-chain.md does for (26).
// X enters as a tilt does: the T̂ directions' amplitude gains τ = J V, V = Ẋ + ω0 J X the joint's velocity in F, so
// τ = J Ẋ − ω0 X, the maps P = J, R = −ω0 of a tilt (general_system.hpp). Its inertia is (26)'s extended chain's
// (base_translation.hpp: the bodies' first moments a_k and the total mass) carried into F, and the tanks' surface forms
// and λ = 0 weights over τ; its modes' couplings are GeneralMode::c_base. No force acts on X, and its row is
//   Jᵀ π̇ + ω0 π = 0,   π = S w + h_X   (w the velocities (δω, τ), S the kinetic form, h_X the liquid's share),
// π the chain's momentum turned by J. So π = 0 holds for all time when it holds once (the system's centre of mass at
// rest), and X itself enters nothing but through τ: the chain's own state (s q, Q̇, Z) stays, with Ẋ from π = 0.
// The axial recoil (a sixth direction, V_z) is not in the tables: the layouts taken have a symmetry about the spin axis
// that decouples it from the tilts (require_symmetric_layout).
#pragma once

#include "general_chain.hpp"
#include "general_system.hpp"

#include <vector>

namespace rc::rom {

// The axial recoil V_z is of order 0 about the spin axis and the tilts of order ±1: a layout of the partially filled
// tanks that a turn of 2π/N (N ≥ 2) maps onto itself couples them through nothing, and only then does the missing sixth
// direction leave the tilts exact (docs/volume.md §8, "The free chain"). The tanks' own shapes are taken to share the
// turn (one tank's tables made for each place; an ellipsoid on the axis). Throws SceneError naming what is taken.
void require_symmetric_layout(const Scene& scene, const std::vector<GeneralBody>& bodies);

// The chain `g` (built from `cm`, (26) of its bodies with their frozen fluid, and `bodies`) extended by X as body n.
// Throws SceneError when the partially filled tanks' layout lacks the symmetry that decouples the axial recoil.
GeneralChain extend_with_recoil(const Scene& scene, const GeneralChain& g, const ChainModel& cm,
                                const std::vector<GeneralBody>& bodies);

// π as a 2 × dim functional on the extended chain's state (s q, Q̇, Z) at the scale s.
Eigen::MatrixXd base_momentum(const GeneralChain& extended, double s);

// The chain's first-order form from the extended one's: X dropped, Ẋ from π = 0. Its recoil_residual holds how far the
// extended form is from the two properties the reduction rests on (X entering only through τ, and π̇ = −ω0 J π).
GeneralSystem reduce_on_recoil(const GeneralChain& g, const GeneralChain& extended, const GeneralSystem& ext);

}  // namespace rc::rom
