#include "base_translation.hpp"

namespace rc::rom {

using cd = std::complex<double>;

namespace {

// Pads an n-square matrix (or n-vector) with a zero row and column for X.
Eigen::MatrixXd padded(const Eigen::MatrixXd& A) {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(A.rows() + 1, A.cols() + 1);
  P.topLeftCorner(A.rows(), A.cols()) = A;
  return P;
}
Eigen::VectorXd padded(const Eigen::VectorXd& v) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(v.size() + 1);
  p.head(v.size()) = v;
  return p;
}

// X's row of the extended inertia: the chain's first moments a (every body moves with the base), its mass, and each
// partially filled tank's K over Y = c u_k + (y_k + X)/L (docs/physics.md §2, "A tank whose joint moves").
void set_base_inertia(const ChainModel& free, const Eigen::VectorXd& a, double mass, Eigen::MatrixXd& M) {
  const int n = free.n;
  M.row(n).head(n) = a.transpose();
  M.col(n).head(n) = a;
  M(n, n) = mass;
  for (int k = 0; k < n; ++k) {
    const BodyModel& b = free.bodies[k];
    if (!b.free_surface) continue;
    M(n, n) += b.K_shift;
    M(n, k) += b.K_cross;
    M(k, n) += b.K_cross;
    for (int j = 0; j < k; ++j) {
      M(n, j) += b.K_shift * free.bodies[j].s;
      M(j, n) += b.K_shift * free.bodies[j].s;
    }
  }
}

}  // namespace

ChainModel extend_with_base(const ChainModel& free, const Eigen::MatrixXd& M_fixed, const Eigen::VectorXd& a,
                            double mass) {
  const int n = free.n;
  ChainModel e;
  e.n = n + 1;
  e.free_chain = false;  // in form: the base is a coordinate, held by nothing
  e.bodies = free.bodies;
  e.bodies.emplace_back();  // X: no mass of its own beyond M's row, no spin, no tank
  e.modes = free.modes;
  for (FluidMode& md : e.modes) {
    if (md.lever_base != 0.0) md.lever.emplace_back(n, md.lever_base);
    md.lever_base = 0;
  }
  e.a = padded(a);
  e.M = padded(M_fixed);
  set_base_inertia(free, a, mass, e.M);
  e.K = padded(free.K);
  e.D = padded(free.D);
  e.G = padded(free.G);
  e.circulatory = padded(free.circulatory);
  e.viscous = free.viscous;
  Eigen::MatrixXcd fluid = Eigen::MatrixXcd::Zero(n + 1, n + 1);
  for (const FluidMode& md : e.modes) add_mode_term(fluid, md, md.E_c());
  for (int k = 0; k < n; ++k) fluid(k, k) += cd(free.bodies[k].E_rem, free.bodies[k].E_rem_imag);
  e.M_eff = e.M - fluid.real();
  e.M_eff_imag = -fluid.imag();
  return e;
}

std::complex<double> base_rate(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w) {
  const ChainModel& e = *m.extended;
  const int X = m.n;
  cd p = 0;
  for (int j = 0; j < m.n; ++j) p += cd(e.M_eff(X, j), e.M_eff_imag(X, j)) * v[j];
  for (int l = 0; l < m.n_modes(); ++l) p += m.modes[l].E_c() * m.modes[l].lever_base * w[l];
  return -p / cd(e.M_eff(X, X), e.M_eff_imag(X, X));
}

std::complex<double> base_rate_from_z(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& z) {
  const ChainModel& e = *m.extended;
  const int X = m.n;
  cd p = 0;
  for (int j = 0; j < m.n; ++j) p += e.M(X, j) * v[j];
  for (int l = 0; l < m.n_modes(); ++l) p += m.modes[l].E_c() * m.modes[l].lever_base * z[l];
  return -p / e.M(X, X);
}

Eigen::MatrixXcd reduce_on_base(const Eigen::MatrixXcd& S) {
  const Eigen::Index n = S.rows() - 1;
  return S.topLeftCorner(n, n) - S.topRightCorner(n, 1) * S.bottomLeftCorner(1, n) / S(n, n);
}

Eigen::MatrixXcd reduced_derivative(const Eigen::MatrixXcd& Phi, const Eigen::MatrixXcd& dPhi) {
  // d(A − b cᵀ/d) = dA − (db cᵀ + b dcᵀ)/d + b cᵀ dd/d²
  const Eigen::Index n = Phi.rows() - 1;
  const cd d = Phi(n, n), dd = dPhi(n, n);
  const Eigen::MatrixXcd b = Phi.topRightCorner(n, 1), c = Phi.bottomLeftCorner(1, n);
  const Eigen::MatrixXcd db = dPhi.topRightCorner(n, 1), dc = dPhi.bottomLeftCorner(1, n);
  return dPhi.topLeftCorner(n, n) - (db * c + b * dc) / d + b * c * (dd / (d * d));
}

template <class Real>
Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic> reduce_first_order(
    const ChainModel& m, const Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic>& B_ext, Real) {
  using C = std::complex<Real>;
  using CMat = Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic>;
  const int n = m.n, nm = m.n_modes(), D = 2 * n + nm;
  // Q: the chain's state -> the extended one (s X = 0: nothing depends on X; Ẋ = base_rate, linear in u̇ and w).
  CMat Q = CMat::Zero(D + 2, D);
  for (int j = 0; j < n; ++j) {
    Q(j, j) = 1;
    Q(n + 1 + j, n + j) = 1;
  }
  for (int l = 0; l < nm; ++l) Q(2 * n + 2 + l, 2 * n + l) = 1;
  for (int j = 0; j < n; ++j) {  // Ẋ's coefficient of u̇_j
    Eigen::VectorXcd v = Eigen::VectorXcd::Zero(n), w = Eigen::VectorXcd::Zero(nm);
    v[j] = 1;
    const cd r = base_rate(m, v, w);
    Q(2 * n + 1, n + j) = C(Real(r.real()), Real(r.imag()));
  }
  for (int l = 0; l < nm; ++l) {  // and of w_l
    Eigen::VectorXcd v = Eigen::VectorXcd::Zero(n), w = Eigen::VectorXcd::Zero(nm);
    w[l] = 1;
    const cd r = base_rate(m, v, w);
    Q(2 * n + 1, 2 * n + l) = C(Real(r.real()), Real(r.imag()));
  }
  // P: the extended rows of s u, u̇ and w (not those of s X and Ẋ).
  // B_ext Q column by column: Q is a selection of B_ext's columns plus the one dense row of Ẋ, so the product is those
  // columns and a rank-one term, O(D²) where the dense product was O(D³) (a fifth of `spectrum`'s time on a table of
  // 774 rows).
  CMat BQ(D + 2, D);
  for (int j = 0; j < n; ++j) {
    BQ.col(j) = B_ext.col(j);
    BQ.col(n + j) = B_ext.col(n + 1 + j);
  }
  for (int l = 0; l < nm; ++l) BQ.col(2 * n + l) = B_ext.col(2 * n + 2 + l);
  BQ.noalias() += B_ext.col(2 * n + 1) * Q.row(2 * n + 1);
  CMat B = CMat::Zero(D, D);
  B.topRows(n) = BQ.topRows(n);
  B.middleRows(n, n) = BQ.middleRows(n + 1, n);
  B.bottomRows(nm) = BQ.bottomRows(nm);
  return B;
}

template Eigen::MatrixXcd reduce_first_order<double>(const ChainModel&, const Eigen::MatrixXcd&, double);
template Eigen::Matrix<std::complex<long double>, Eigen::Dynamic, Eigen::Dynamic> reduce_first_order<long double>(
    const ChainModel&, const Eigen::Matrix<std::complex<long double>, Eigen::Dynamic, Eigen::Dynamic>&, long double);

}  // namespace rc::rom
