#include "characteristic.hpp"

#include "base_translation.hpp"
#include "complex_svd.hpp"

#include "eigen_dense.hpp"
#include <cmath>
#include <limits>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

struct Terms {
  Eigen::MatrixXcd Phi;
  double norm_sum = 0;
};

Terms evaluate(const ChainModel& m, cd sigma) {
  const int n = m.n;
  const cd I(0, 1);
  Terms t;
  // Kononov (22)/(29): F_k on the diagonal, M_ki (+ kappa^2/sigma^2) off it.
  t.Phi = m.M.cast<cd>();
  t.norm_sum = m.M.norm();
  Eigen::MatrixXcd gyro = Eigen::MatrixXcd::Zero(n, n), fluid = Eigen::MatrixXcd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    gyro(k, k) = m.G[k] / sigma;
    fluid(k, k) = cd(m.bodies[k].E_rem, m.bodies[k].E_rem_imag);  // static correction: frequency-independent inertia
  }
  for (const auto& md : m.modes) {
    const double w0 = m.bodies[md.body].omega;
    add_mode_term(fluid, md, (sigma + w0) * md.E_c() / (sigma + w0 - md.lambda_c()));
  }
  Eigen::MatrixXcd damp = (-I / sigma) * m.D.cast<cd>();
  Eigen::MatrixXcd stiff = (-1.0 / (sigma * sigma)) * complex_stiffness(m);
  t.Phi += gyro + damp + stiff - fluid;
  t.norm_sum += gyro.norm() + damp.norm() + stiff.norm() + fluid.norm();
  return t;
}
}  // namespace

// A free chain with a partially filled tank: the extended chain's Φ reduced on its base's translation
// (base_translation.hpp).
Eigen::MatrixXcd characteristic_matrix(const ChainModel& m, cd sigma) {
  if (m.extended) return reduce_on_base(evaluate(*m.extended, sigma).Phi);
  return evaluate(m, sigma).Phi;
}

Eigen::MatrixXcd characteristic_derivative(const ChainModel& m, cd sigma) {
  if (m.extended) return reduced_derivative(evaluate(*m.extended, sigma).Phi, characteristic_derivative(*m.extended, sigma));
  const int n = m.n;
  const cd I(0, 1);
  Eigen::MatrixXcd d = (I / (sigma * sigma)) * m.D.cast<cd>() + (2.0 / (sigma * sigma * sigma)) * complex_stiffness(m);
  for (int k = 0; k < n; ++k) d(k, k) -= m.G[k] / (sigma * sigma);
  for (const auto& md : m.modes) {
    const cd p = sigma + m.bodies[md.body].omega - md.lambda_c();
    add_mode_term(d, md, md.E_c() * md.lambda_c() / (p * p));  // -d/dsigma of (sigma + w0) E/(sigma + w0 - lambda)
  }
  return d;
}

double characteristic_residual(const ChainModel& m, cd sigma, double scale) {
  if (m.extended) return characteristic_residual(*m.extended, sigma, scale);  // its Φ vanishes where the reduced one does
  const double tiny = 1e-9 * scale;
  const bool has_inverse_terms =
      m.G.cwiseAbs().maxCoeff() > 0 || m.has_friction() || m.K.cwiseAbs().maxCoeff() > 0 || m.has_circulatory();
  if (has_inverse_terms && std::abs(sigma) <= tiny) return std::numeric_limits<double>::quiet_NaN();
  for (const auto& md : m.modes)
    if (std::abs(sigma + m.bodies[md.body].omega - md.lambda_c()) <= tiny)
      return std::numeric_limits<double>::quiet_NaN();
  Terms t = evaluate(m, sigma);
  // Values only, by divide and conquer (LAPACK's zgesdd; Jacobi is O(n^3) with a large constant: 12 s at n = 100).
  return singular_values(t.Phi, "the characteristic matrix").minCoeff() / t.norm_sum;
}

}  // namespace rc::rom
