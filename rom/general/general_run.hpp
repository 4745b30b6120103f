// Time histories of the chain without axial symmetry (`chain-rom run`; docs/rom.md, "Bodies and tanks without axial
// symmetry"): general_system.hpp's first-order form propagated exactly, y_{j+1} = exp(B h) y_j over each output step
// h — or, at two spins (periodic coefficients), by floquet.hpp's Magnus steps, as many a period as its roots settled
// with —, from the scene's tilts, rates and fluid amplitudes, and written in (26)'s terms: u_k = e^{−iω0t}(q_x − i q_y)
// in space.
#pragma once

#include "general_chain.hpp"
#include "general_system.hpp"
#include "propagation.hpp"
#include "scene.hpp"

#include <limits>
#include <vector>

namespace rc::rom {

struct GeneralHistory {
  std::vector<double> t;
  History::Rows u;       // steps × n: (26)'s complex tilts in space
  History::Rows z;       // steps × modes: the fluid's amplitudes (general_tank.hpp: h = Σ 2 Re(z c))
  Eigen::MatrixXd spin;  // steps × n: ω0 + ψ̇_k when the spins' rates are coordinates (3-D tanks), else empty
  // One body without gravity, friction or field: its angular momentum perturbation in space (about O, or its centre
  // of mass when free), conserved by the linear equations: max_t |δL(t) − δL(0)| over the largest of its terms
  // (C ω0 n_t, I δω, h). NaN when the chain has no such integral.
  double momentum_drift = std::numeric_limits<double>::quiet_NaN();
  double wall_seconds = 0;
};

// Throws SceneError naming the key for what drives the chain in a linear run and is not modelled there yet: external
// moments and forces, a field's transverse parts (the aerodynamic moments and a field's axial part are in its matrices).
void require_unforced(const Scene& scene);

// y(0) from the scene's u_k(0), u̇_k(0), the spins at ω0 and the fluid's modes at `initial.fluid` (each mode's z(0),
// general_tank.hpp; at rest without it). Throws SceneError for a change of spin, a count of fluid pairs that is not
// the kept modes', and as require_unforced.
Eigen::VectorXd general_initial_state(const GeneralChain& g, const GeneralSystem& sys, const Scene& scene);

// Throws std::runtime_error for what the general run does not take (a method other than "exact") and when the trajectory leaves double precision. At two spins `steps_per_period` > 0 is the Magnus steps
// a period the roots settled with (general_spectrum's floquet_steps), else they are settled here.
GeneralHistory propagate_general(const GeneralChain& g, const Scene& scene, int steps_per_period = 0);

}  // namespace rc::rom
