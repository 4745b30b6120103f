// The linear chain's time integrators (run.method; docs/rom.md, "Propagation (`run`)" and "Source layout"). Each is one
// file under linear/integrators/ defining a LinearIntegrator, and one line in integrator_registry.cpp; propagate()
// (propagation.hpp) and the drivers' scene check find it there by name.
#pragma once

#include "chain_model.hpp"
#include "first_order_system.hpp"
#include "history.hpp"
#include "scene.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace rc::rom {

// Where an integrator puts the states of y' = B y it computes (propagation.cpp's recorder): one at a time, or a block
// of consecutive output times as the columns of re + i im.
class StateSink {
 public:
  virtual ~StateSink() = default;
  virtual void store(long j, const Eigen::VectorXcd& y) = 0;
  virtual void store_block(long j0, const Eigen::Ref<const Eigen::MatrixXd>& re,
                           const Eigen::Ref<const Eigen::MatrixXd>& im) = 0;
};

// One run: the states y(j h), j = 0 … steps, from y0 (rho: the fastest root's |sigma|, for the step-controlled ones).
struct IntegratorRun {
  const ChainModel& model;
  const FirstOrderSystem& system;
  const Eigen::VectorXcd& y0;
  double h = 0;
  long steps = 0;
  double rho = 0;
  const RunSpec& run;
  StateSink& sink;
  History& history;  // method_used, integrator_steps, eigvec_condition
};

struct LinearIntegrator {
  std::string name;                                    // run.method's value
  double (*estimate_steps)(double rho, const RunSpec&);  // before any work; nullptr: not step-controlled (no guard)
  void (*run)(const IntegratorRun&);
};

// Every integrator, in registration order.
const std::vector<LinearIntegrator>& linear_integrators();
// The one run.method names: throws SceneError("<file>: run.method: must be one of …") for a name none has.
const LinearIntegrator& linear_integrator(const Scene& scene);

// Step-count guard of the integrators (docs/rom.md, "Limits"): gauss and rk45 refuse a run whose
// estimated number of steps exceeds this, naming the estimate and pointing to method = "exact".
inline constexpr double kMaxIntegratorSteps = 1e7;

// Estimated steps of `method` ("gauss" or "rk45"; 0 for anything else) over run.t_end for a system
// whose fastest root has |sigma| = rho (rad/s):
//   gauss: t_end / h_s with t_end rho^5 h_s^4 / 4320 = tolerance (the substep rule of propagate);
//   rk45:  t_end rho / min(3, (tolerance / 8e-4)^(1/5))  (Dormand-Prince's local error estimate is
//          about 8e-4 (rho h)^5 on y' = i rho y; 3 is near its stability limit on the imaginary axis),
// and never fewer than the number of output steps.
// By name (0 for "exact" and for a name no integrator has).
double estimate_integrator_steps(const std::string& method, double rho, const RunSpec& run);

// The integrators' steps on y' = B y (also used by `chain-rom bench` for its work-precision sweep):
// 2-stage Gauss-Legendre over a step h is the (2,2) Pade approximant of exp(B h),
//   P = (I - Bh/2 + (Bh)^2/12)^{-1} (I + Bh/2 + (Bh)^2/12),   y_{j+1} = P y_j;
Eigen::MatrixXcd gauss_step_matrix(const Eigen::MatrixXcd& B, double h);
// Dormand-Prince 5(4) from t0 to t1 with error control `tol` (relative to 1 + |y|); h is the step
// to try first and comes back as the next step to try; steps counts accepted + rejected steps.
void rk45_advance(const Eigen::MatrixXcd& B, Eigen::VectorXcd& y, double t0, double t1, double tol, double& h,
                  long& steps);

}  // namespace rc::rom
