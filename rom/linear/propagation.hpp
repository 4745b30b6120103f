// Time histories of u_k and the fluid coordinates by propagation of the linear constant-coefficient first-order
// system (first_order_system.hpp) with the integrator run.method names (integrator.hpp):
//   exact: y(t) = V e^{i sigma t} V^{-1} y(0) evaluated at every output time (no accumulation);
//          when V is ill-conditioned (defective spectrum) y_{j+1} = exp(B h) y_j instead;
//   gauss: 2-stage Gauss-Legendre (the (2,2) Pade approximant of exp, which keeps quadratic
//          invariants), substeps chosen from run.tolerance;
//   rk45:  Dormand-Prince with error control run.tolerance.
#pragma once

#include "chain_model.hpp"
#include "history.hpp"
#include "integrator.hpp"
#include "scene.hpp"

#include <limits>
#include <string>
#include <vector>

namespace rc::rom {


// Throws std::runtime_error naming the method, the estimate, the limit and suggesting method =
// "exact" if gauss or rk45 would need more than kMaxIntegratorSteps; before any time stepping.
History propagate(const ChainModel& m, const Scene& scene);

}  // namespace rc::rom
