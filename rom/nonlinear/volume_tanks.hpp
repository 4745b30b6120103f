// The nonlinear chain's bodies when the scene has tanks without axial symmetry (docs/rom.md, "Nonlinear chain",
// "Tanks without axial symmetry"): products of inertia, several tanks on a body, a tank off its body's axis or a 3-D
// table. Each body is then taken as the general chain takes it (general_chain.hpp, general_bodies: the shell with its
// frozen liquid about O_k, every tank's kept modes as coupling vectors, the λ = 0 weight), turned to its principal
// axes, and its tanks' liquid ridden in its frame by volume_fluid.hpp.
#pragma once

#include "chain_model.hpp"
#include "nonlinear_chain.hpp"
#include "scene.hpp"

namespace rc::rom {

// Whether the scene's tanks go through volume_fluid.hpp (else the axisymmetric tank model of nonlinear_chain.hpp).
// Throws SceneError naming the key on a table that cannot be read.
bool needs_volume_tanks(const Scene& scene, TableCache& tables);

// The chain's bodies (mass, centre of mass, principal moments and turn, next joint, liquid). Throws SceneError naming
// the key for what general_bodies refuses and for a body whose inertia less the liquid's share (what the modes do not
// carry rigidly) is not positive definite.
std::vector<ChainBody> volume_tank_bodies(const Scene& scene, TableCache& tables);

}  // namespace rc::rom
