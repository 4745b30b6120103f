// run.method = "gauss": 2-stage Gauss-Legendre, the (2,2) Pade approximant of exp(B h), which keeps quadratic
// invariants; substeps from run.tolerance.
#include "integrator.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>

namespace rc::rom {

Eigen::MatrixXcd gauss_step_matrix(const Eigen::MatrixXcd& B, double h) {
  const Eigen::MatrixXcd Z = B * std::complex<double>(h), Z2 = Z * Z;
  const Eigen::MatrixXcd Id = Eigen::MatrixXcd::Identity(B.rows(), B.cols());
  return Eigen::PartialPivLU<Eigen::MatrixXcd>(Id - 0.5 * Z + Z2 / 12.0).solve(Id + 0.5 * Z + Z2 / 12.0);
}

namespace {

// t_end rho^5 hs^4 / 4320 = tolerance: the substep (docs/rom.md, "Propagation (`run`)").
double gauss_substep(double rho, const RunSpec& run) {
  return std::pow(4320.0 * run.tolerance / (run.t_end * std::pow(rho, 5)), 0.25);
}

double estimate_gauss_steps(double rho, const RunSpec& run) {
  const double outputs = std::floor(run.t_end / run.output_step + 1e-9);
  if (!(rho > 0)) return outputs;
  return std::max(outputs, outputs * std::ceil(run.output_step / gauss_substep(rho, run)));
}

// Global error ~ t_end rho^5 hs^4 / 4320 <= tol.
void run_gauss(const IntegratorRun& r) {
  const double h = r.h, rho = r.rho;
  const long steps = r.steps;
  const RunSpec& run = r.run;
  StateSink& rec = r.sink;
  History& hist = r.history;
  long sub = 1;
  if (rho > 0) sub = std::max(1L, static_cast<long>(std::ceil(h / gauss_substep(rho, run))));
  if (sub * steps > 200000000L) throw std::runtime_error("run.tolerance: gauss needs more than 2e8 steps");
  const double hs = h / sub;
  const Eigen::MatrixXcd P = gauss_step_matrix(r.system.B, hs);
  Eigen::VectorXcd y = r.y0;
  rec.store(0, y);
  for (long j = 1; j <= steps; ++j) {
    for (long s = 0; s < sub; ++s) y = P * y;
    rec.store(j, y);
  }
  hist.method_used = "gauss (" + std::to_string(sub) + " substeps per output step)";
  hist.integrator_steps = sub * steps;
}

}  // namespace

LinearIntegrator gauss_integrator() { return {"gauss", estimate_gauss_steps, run_gauss}; }

}  // namespace rc::rom
