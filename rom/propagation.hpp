// Time histories of u_k and the fluid coordinates by exact propagation of the linear
// constant-coefficient first-order system (first_order_system.hpp):
//   exact: y(t) = V e^{i sigma t} V^{-1} y(0) evaluated at every output time (no accumulation);
//          when V is ill-conditioned (defective spectrum) y_{j+1} = exp(B h) y_j instead;
//   gauss: 2-stage Gauss-Legendre (the (2,2) Pade approximant of exp, which keeps quadratic
//          invariants), substeps chosen from run.tolerance;
//   rk45:  Dormand-Prince with error control run.tolerance.
#pragma once

#include "chain_model.hpp"
#include "scene.hpp"

#include <string>
#include <vector>

namespace rc::rom {

struct History {
  std::vector<double> t;
  Eigen::MatrixXcd u;       // steps x n
  Eigen::MatrixXcd z;       // steps x n_modes: scaled fluid coordinates, S'_kl = (a/N^2)_kl z_kl
  std::vector<double> H;    // energy (energy.hpp)
  std::vector<double> H_scale;
  std::string method_used;  // what actually ran
  double max_energy_drift = 0;  // max |H - H0| / scale(0) (undamped) or max increase (damped)
  double wall_seconds = 0;
};

History propagate(const ChainModel& m, const Scene& scene);

}  // namespace rc::rom
