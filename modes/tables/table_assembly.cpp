#include "table_assembly.hpp"

#include <cmath>
#include <limits>

namespace rc::modes {

ModeTable start_table(const geometry::ShapeSpec& shape, const FluidIntegrals& fluid, double J_zh) {
  ModeTable t;
  t.shape = shape.kind;
  t.dimensions = shape.dims;
  t.m = 1;
  t.volume = fluid.volume;
  t.centroid_z = fluid.centroid_z;
  t.A_f = fluid.A_f;
  t.C_f = fluid.C_f;
  t.J_zh = J_zh;
  t.sum_rule = fluid.A_f - J_zh;
  t.normalisation = "rho = 1, omega0 = 1; each cluster's V is normalised to N2 = |V|^2 = 1, a = (e1 x r, V), "
                    "so E = 2 a^2 / N2 (docs/physics.md §2)";
  return t;
}

void add_modes(ModeTable& t, const std::vector<Cluster>& clusters) {
  double kept = 0;
  for (const auto& c : clusters) {
    t.lambda.push_back(c.lambda);
    t.kappa.push_back(2 / c.lambda);
    t.E.push_back(c.E);
    t.a.push_back(std::sqrt(c.E / 2));
    t.N2.push_back(1.0);
    // Relative residuals of the discrete eigenproblem: a bound below the rounding of the arithmetic says no more
    // than "solved to working precision", so it is stored as that (docs/modes.md, "The residual column").
    t.residual.push_back(std::max(c.residual, std::numeric_limits<double>::epsilon()));
    t.spread.push_back(c.spread);
    t.members.push_back(c.members);
    kept += c.E;
  }
  t.coverage = t.sum_rule > 0 ? kept / t.sum_rule : 1.0;
}

void add_convergence(ModeTable& t, const ConvergenceCheck& check, double tolerance) {
  t.convergence_reference = check.reference;
  t.convergence_tolerance = tolerance;
  for (const auto& ch : check.changes) {
    t.dlambda.push_back(ch.dlambda);
    t.dE.push_back(ch.dE);
    t.converged.push_back(ch.converged ? 1 : 0);
  }
}

void add_bands(ModeTable& t, const BandWeights& bands) {
  t.bands.lo = bands.lo;
  t.bands.hi = bands.hi;
  t.bands.E = bands.E;
  t.bands.lambda_mean = bands.lambda_mean;
}

}  // namespace rc::modes
