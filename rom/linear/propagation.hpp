// Time histories of u_k and the fluid coordinates by exact propagation of the linear
// constant-coefficient first-order system (first_order_system.hpp):
//   exact: y(t) = V e^{i sigma t} V^{-1} y(0) evaluated at every output time (no accumulation);
//          when V is ill-conditioned (defective spectrum) y_{j+1} = exp(B h) y_j instead;
//   gauss: 2-stage Gauss-Legendre (the (2,2) Pade approximant of exp, which keeps quadratic
//          invariants), substeps chosen from run.tolerance;
//   rk45:  Dormand-Prince with error control run.tolerance.
#pragma once

#include "chain_model.hpp"
#include "energy_budget.hpp"
#include "galerkin_energy.hpp"
#include "scene.hpp"

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
  // The spins' own motion (axial_rotation.hpp), when axial friction or moments move them: steps x n, else empty.
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

// Step-count guard of the integrators (docs/rom.md, "Limits"): gauss and rk45 refuse a run whose
// estimated number of steps exceeds this, naming the estimate and pointing to method = "exact".
inline constexpr double kMaxIntegratorSteps = 1e7;

// Estimated steps of `method` ("gauss" or "rk45"; 0 for anything else) over run.t_end for a system
// whose fastest root has |sigma| = rho (rad/s):
//   gauss: t_end / h_s with t_end rho^5 h_s^4 / 4320 = tolerance (the substep rule of propagate);
//   rk45:  t_end rho / min(3, (tolerance / 8e-4)^(1/5))  (Dormand-Prince's local error estimate is
//          about 8e-4 (rho h)^5 on y' = i rho y; 3 is near its stability limit on the imaginary axis),
// and never fewer than the number of output steps.
double estimate_integrator_steps(const std::string& method, double rho, const RunSpec& run);

// The integrators' steps on y' = B y (also used by `chain-rom bench` for its work-precision sweep):
// 2-stage Gauss-Legendre over a step h is the (2,2) Pade approximant of exp(B h),
//   P = (I - Bh/2 + (Bh)^2/12)^{-1} (I + Bh/2 + (Bh)^2/12),   y_{j+1} = P y_j;
Eigen::MatrixXcd gauss_step_matrix(const Eigen::MatrixXcd& B, double h);
// Dormand-Prince 5(4) from t0 to t1 with error control `tol` (relative to 1 + |y|); h is the step
// to try first and comes back as the next step to try; steps counts accepted + rejected steps.
void rk45_advance(const Eigen::MatrixXcd& B, Eigen::VectorXcd& y, double t0, double t1, double tol, double& h,
                  long& steps);

// Throws std::runtime_error naming the method, the estimate, the limit and suggesting method =
// "exact" if gauss or rk45 would need more than kMaxIntegratorSteps; before any time stepping.
History propagate(const ChainModel& m, const Scene& scene);

}  // namespace rc::rom
