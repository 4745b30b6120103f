#include "root_newton.hpp"

#include "characteristic.hpp"

#include "eigen_dense.hpp"
#include <cmath>

namespace rc::rom {

NewtonRoot newton_root(const ChainModel& m, std::complex<double> sigma0, double scale) {
  using cd = std::complex<double>;
  NewtonRoot r;
  r.sigma = sigma0;
  const double tiny = 1e-14 * std::max(scale, 1e-300);
  for (r.iterations = 0; r.iterations < 50; ++r.iterations) {
    const Eigen::MatrixXcd Phi = characteristic_matrix(m, r.sigma);
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(Phi);
    // A zero pivot: Phi exactly singular, sigma is on the root (the determinant itself would under- or
    // overflow for large chains long before it is exactly 0).
    if ((lu.matrixLU().diagonal().array() == cd(0)).any()) { r.converged = true; return r; }
    const cd trace = lu.solve(characteristic_derivative(m, r.sigma)).trace();
    if (!std::isfinite(std::abs(trace)) || trace == 0.0) return r;
    const cd step = -1.0 / trace;
    r.sigma += step;
    if (!std::isfinite(std::abs(r.sigma))) return r;
    if (std::abs(step) <= tiny) { r.converged = true; ++r.iterations; return r; }
  }
  return r;
}

}  // namespace rc::rom
