#include "real_root_certificate.hpp"

#include "characteristic.hpp"

#include "eigen_dense.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rc::rom {
namespace {

// sign of P(t) (header): +1, −1, or 0 where it cannot be told (an exact zero pivot, t at a pole).
int sign_of_p(const ChainModel& m, double t) {
  // A free chain with a partially filled tank: P is the extended chain's (base_translation.hpp); the reduced Φ's
  // determinant changes sign also where its X entry vanishes, which is no root.
  const Eigen::MatrixXd Phi = characteristic_matrix(m.extended ? *m.extended : m, {t, 0.0}).real();
  if (!Phi.allFinite()) return 0;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Phi);
  int sign = static_cast<int>(std::lround(lu.permutationP().determinant()));
  for (Eigen::Index i = 0; i < Phi.rows(); ++i) {
    const double pivot = lu.matrixLU()(i, i);
    if (pivot == 0 || !std::isfinite(pivot)) return 0;
    if (pivot < 0) sign = -sign;
  }
  for (const FluidMode& md : m.modes) {
    const double factor = t - (md.lambda - m.bodies[md.body].omega);
    if (factor == 0) return 0;
    if (factor < 0) sign = -sign;
  }
  return sign;  // σ^{2n} > 0
}

}  // namespace

RealRootCertificate certify_real_roots(const ChainModel& m, const Spectrum& sp) {
  RealRootCertificate c;
  if (m.dissipative() || sp.roots.empty()) return c;
  c.applies = true;
  std::vector<double> re;
  for (const Root& r : sp.roots) {
    if (std::abs(r.sigma) <= sp.tolerance) ++c.at_zero;
    else re.push_back(r.sigma.real());
  }
  c.roots = static_cast<int>(re.size());
  if (re.empty()) return c;
  // The roots in order, σ = 0 as one marker for the zero roots (NaN), then sample points: before the first, between
  // consecutive ones, after the last; on either side of σ = 0 just outside it, with a break (NaN) between, so that
  // the zero roots fall in no counted interval.
  std::vector<double> at = re;
  if (c.at_zero > 0) at.push_back(0.0);
  std::sort(at.begin(), at.end());
  const double radius = std::max({std::abs(at.front()), std::abs(at.back()), 1.0});
  const double zero = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t{at.front() - 0.5 * radius};
  for (std::size_t j = 0; j + 1 < at.size(); ++j) {
    const double a = at[j], b = at[j + 1];
    const bool a_zero = c.at_zero > 0 && a == 0.0, b_zero = c.at_zero > 0 && b == 0.0;
    if (b_zero) {
      t.push_back(std::max(0.5 * a, -2 * sp.tolerance));
      t.push_back(zero);
    } else if (a_zero) {
      t.push_back(std::min(0.5 * b, 2 * sp.tolerance));
    } else {
      t.push_back(0.5 * (a + b));
    }
  }
  t.push_back(at.back() + 0.5 * radius);
  int previous = 0;
  for (double x : t) {
    if (std::isnan(x)) { previous = 0; continue; }
    const int s = sign_of_p(m, x);
    if (previous != 0 && s != 0 && s != previous) ++c.proven;
    if (s != 0) previous = s;
  }
  return c;
}

}  // namespace rc::rom
