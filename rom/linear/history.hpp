// What a linear run of (26) leaves (propagation.hpp): the output times, the tilts and fluid coordinates, the energy or
// its budget, and what the integrator did.
#pragma once

#include "energy_budget.hpp"
#include "galerkin_energy.hpp"

#include <Eigen/Core>

#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace rc::rom {

struct History {
  // Row-major: one output time per row, stored contiguously (exact propagation writes whole blocks
  // of rows at once).
  using Rows = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<double> t;
  Rows u;                   // steps x n
  Rows z;                   // steps x n_modes: scaled fluid coordinates, S'_kl = (a/N^2)_kl z_kl
  std::vector<double> H;    // energy (energy.hpp)
  std::vector<double> H_scale;
  EnergyBudget budget;      // with viscous tanks (which leave no energy integral H): the frozen chain's budget
  EnergyBalance balance;    // with viscous tanks whose fluid holds an energy (Galerkin tanks, one spin): H and its
                            // dissipation (galerkin_energy.hpp); empty otherwise
  bool forced = false;      // external moments (forced_solution.hpp): H is then not an integral
  // Forced, ideal tanks: max_t |H(t) − H(0) − W(t)| / max_t scale(t), W the work of the external moments, forces and field
  // less the friction's, ∫ Re(F̄ᵀu̇) − u̇ᴴDu̇ by the trapezoid rule on the output samples (Batyr (11)); NaN otherwise.
  double work_balance = std::numeric_limits<double>::quiet_NaN();
  // The spins' own motion (axial_rotation.hpp), when axial friction, moments or initial.axial_rate move them: steps x n,
  // else empty.
  Eigen::MatrixXd spin, axial_angle;
  std::string method_used;  // what actually ran
  double max_energy_drift = 0;  // max |H - H0| / scale(0) (undamped) or max increase (damped)
  double wall_seconds = 0;
  double cpu_seconds = 0;       // process CPU time of propagate (all threads)
  long integrator_steps = 0;    // gauss substeps / accepted+rejected rk45 steps; exact: matrix products
  double eigvec_condition = 0;  // exact: 2-norm condition number of the eigenvector matrix V
  // The linear model's validity at this amplitude (linear_validity.hpp), filled by `chain-rom run`: the nonlinear
  // chain's relative tilt difference, and the amplitude at which it reaches 1 %; empty note = measured.
  double nonlinear_difference = -1, amplitude_at_limit = -1;
  std::string validity_note;
};

}  // namespace rc::rom
