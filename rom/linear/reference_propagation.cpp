#include "reference_propagation.hpp"

#include "balancing.hpp"
#include "first_order_system.hpp"

#include <unsupported/Eigen/MatrixFunctions>
#include "eigen_dense.hpp"

#include <cfloat>
#include <chrono>
#include <stdexcept>

namespace rc::rom {

namespace {

using LC = std::complex<long double>;
using LCMat = Eigen::Matrix<LC, Eigen::Dynamic, Eigen::Dynamic>;
using LCVec = Eigen::Matrix<LC, Eigen::Dynamic, 1>;

// Both long double methods on B (balanced here: B = S Bb S^{-1}, exactly, powers of two).
ReferenceState propagate_long_double(LCMat Bb, const Eigen::VectorXcd& y0, double t) {
  const auto start = std::chrono::steady_clock::now();
  const Eigen::VectorXd S = balance_in_place(Bb);
  const Eigen::Matrix<long double, Eigen::Dynamic, 1> Sl = S.cast<long double>();
  const LCVec x0 = (y0.cast<LC>().array() / Sl.cast<LC>().array()).matrix();  // S^{-1} y0
  const long double tl = static_cast<long double>(t);

  Eigen::ComplexEigenSolver<LCMat> es(Bb, true);
  if (es.info() != Eigen::Success) throw std::runtime_error("reference: long double eigen-solver did not converge");
  const LCVec c = Eigen::PartialPivLU<LCMat>(es.eigenvectors()).solve(x0);
  LCVec e(c.size());
  for (Eigen::Index i = 0; i < c.size(); ++i) e[i] = std::exp(es.eigenvalues()[i] * tl) * c[i];
  const LCVec y_eig = (Sl.cast<LC>().array() * (es.eigenvectors() * e).array()).matrix();

  const LCMat Bt = Bb * LC(tl);
  const LCVec y_expm = (Sl.cast<LC>().array() * (Bt.exp() * x0).array()).matrix();

  ReferenceState r;
  r.y = y_eig.cast<std::complex<double>>();
  r.method_difference = static_cast<double>((y_eig - y_expm).norm() / y_eig.norm());
  r.mantissa_bits = LDBL_MANT_DIG;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

ReferenceState reference_state(const ChainModel& m, double s, const Eigen::VectorXcd& y0, double t) {
  return propagate_long_double(first_order_matrix<long double>(m, static_cast<long double>(s)), y0, t);
}

ReferenceState reference_state(const Eigen::MatrixXcd& B, const Eigen::VectorXcd& y0, double t) {
  return propagate_long_double(B.cast<LC>(), y0, t);
}

}  // namespace rc::rom
