#include "free_surface_radial.hpp"

#include "line_space.hpp"
#include "separable_forms.hpp"

#include "eigen_dense.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rc::modes {

std::vector<double> free_surface_radial_eigenvalues(double a, double b, double k, int order, int elements) {
  if (!(b > 0 && b < a)) throw std::invalid_argument("free_surface_radial_eigenvalues: needs 0 < b < a");
  const LineSpace R(graded_breaks(b, a, elements, 2, true, true), order, false);
  const RadialForms f = radial_forms(R);
  const int n = R.ndof();
  // The dof at r = b: the partition's first node (LineSpace numbers the nodes from the left).
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  S(0, 0) = 1;
  const Eigen::MatrixXd P0 = -4 * k * k * f.B, P1 = 2 * f.C, P2 = f.A + k * k * f.B + 4 * S, P4 = -S;
  // Companion form of λ⁴P4 + λ²P2 + λP1 + P0 (no λ³ term): with z = (x, λx, λ²x, λ³x),
  //   [0 I 0 0; 0 0 I 0; 0 0 0 I; −P0 −P1 −P2 0] z = λ diag(I, I, I, P4) z.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(4 * n, 4 * n), M = Eigen::MatrixXd::Identity(4 * n, 4 * n);
  for (int i = 0; i < 3; ++i) L.block(i * n, (i + 1) * n, n, n).setIdentity();
  L.block(3 * n, 0, n, n) = -P0;
  L.block(3 * n, n, n, n) = -P1;
  L.block(3 * n, 2 * n, n, n) = -P2;
  M.block(3 * n, 3 * n, n, n) = P4;
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(L, M, false);
  if (ges.info() != Eigen::Success) throw std::runtime_error("free-surface radial problem: the QZ eigensolver failed");
  std::vector<double> out;
  const Eigen::VectorXcd alpha = ges.alphas();
  const Eigen::VectorXd beta = ges.betas();
  const double scale = L.norm() / M.norm();
  for (Eigen::Index i = 0; i < alpha.size(); ++i) {
    if (std::abs(beta[i]) <= 1e-10 * std::abs(alpha[i]) || std::abs(alpha[i]) > 1e8 * scale * std::abs(beta[i]))
      continue;  // infinite: P4 is singular
    const std::complex<double> l = alpha[i] / beta[i];
    if (std::abs(l.imag()) > 1e-8 * std::max(1.0, std::abs(l)))
      throw std::runtime_error("free-surface radial problem: a complex eigenvalue " + std::to_string(l.real()) + " + " +
                               std::to_string(l.imag()) + "i");
    out.push_back(l.real());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace rc::modes
