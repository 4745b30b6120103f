#include "window_weight.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace rc::modes {

WindowWeight weigh_window(const QuadraticEigenSolver& solver, double lo, double hi) {
  if (!(lo < hi && lo > -2 && hi < 2))
    throw std::runtime_error(fmt::format("window [{:g}, {:g}): need -2 < LO < HI < 2", lo, hi));
  WindowWeight w;
  w.lo = lo;
  w.hi = hi;
  double El = 0;
  for (const auto& p : solver.solve_interval(lo, hi).pairs) {
    ++w.pairs;
    w.E += p.coupling.E;
    El += p.coupling.E * p.lambda;
    if (p.coupling.E > w.E_max) { w.E_max = p.coupling.E; w.lambda_of_E_max = p.lambda; }
  }
  w.lambda_mean = w.E > 0 ? El / w.E : 0.0;
  return w;
}

}  // namespace rc::modes
