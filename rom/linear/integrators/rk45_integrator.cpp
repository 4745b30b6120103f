// run.method = "rk45": Dormand-Prince 5(4) with its own step control (error run.tolerance), stopping at every output
// time.
#include "integrator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rc::rom {

void rk45_advance(const Eigen::MatrixXcd& B, Eigen::VectorXcd& y, double t0, double t1, double tol, double& h,
                  long& steps) {
  static const double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  static const double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45,
                      a42 = -56.0 / 15, a43 = 32.0 / 9, a51 = 19372.0 / 6561,
                      a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729,
                      a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                      a64 = 49.0 / 176, a65 = -5103.0 / 18656, b1 = 35.0 / 384,
                      b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  static const double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                      e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
  (void)c2; (void)c3; (void)c4; (void)c5;
  double t = t0;
  Eigen::VectorXcd k1 = B * y;
  while (t < t1 - 1e-14 * std::abs(t1)) {
    if (t + h > t1) h = t1 - t;
    Eigen::VectorXcd k2 = B * (y + h * a21 * k1);
    Eigen::VectorXcd k3 = B * (y + h * (a31 * k1 + a32 * k2));
    Eigen::VectorXcd k4 = B * (y + h * (a41 * k1 + a42 * k2 + a43 * k3));
    Eigen::VectorXcd k5 = B * (y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
    Eigen::VectorXcd k6 = B * (y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
    Eigen::VectorXcd yn = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    Eigen::VectorXcd k7 = B * yn;
    Eigen::VectorXcd err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    const double sc = tol * (1 + std::max(y.norm(), yn.norm()));
    const double r = err.norm() / sc;
    if (++steps > 100000000L) throw std::runtime_error("run.tolerance: rk45 needs more than 1e8 steps");
    if (r <= 1) {
      t += h;
      y = yn;
      k1 = k7;
    }
    h *= std::min(5.0, std::max(0.2, 0.9 * std::pow(std::max(r, 1e-300), -0.2)));
  }
}

namespace {

// Dormand-Prince's local error estimate is about 8e-4 (rho h)^5 on y' = i rho y; 3 is near its stability limit on the
// imaginary axis.
double estimate_rk45_steps(double rho, const RunSpec& run) {
  const double outputs = std::floor(run.t_end / run.output_step + 1e-9);
  if (!(rho > 0)) return outputs;
  const double rho_h = std::min(3.0, std::pow(run.tolerance / 8e-4, 0.2));
  return std::max(outputs, run.t_end * rho / rho_h);
}

// method = "rk45": Dormand-Prince with its own step control, stopping at every output time.
void run_rk45(const IntegratorRun& r) {
  const double h = r.h;
  const long steps = r.steps;
  const RunSpec& run = r.run;
  StateSink& rec = r.sink;
  History& hist = r.history;
  Eigen::VectorXcd y = r.y0;
  rec.store(0, y);
  double hh = h;
  long nsteps = 0;
  for (long j = 1; j <= steps; ++j) {
    rk45_advance(r.system.B, y, (j - 1) * h, j * h, run.tolerance, hh, nsteps);
    rec.store(j, y);
  }
  hist.method_used = "rk45 (" + std::to_string(nsteps) + " steps)";
  hist.integrator_steps = nsteps;
}

}  // namespace

LinearIntegrator rk45_integrator() { return {"rk45", estimate_rk45_steps, run_rk45}; }

}  // namespace rc::rom
