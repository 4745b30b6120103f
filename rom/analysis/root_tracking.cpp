#include "root_tracking.hpp"

#include "first_order_system.hpp"

#include "eigen_dense.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace rc::rom {
namespace {
using cd = std::complex<double>;
// The n x n matrices of (22) on the stack: a map point evaluates f'/f thousands of times.
using SmallMat = Eigen::Matrix<cd, Eigen::Dynamic, Eigen::Dynamic, 0, CharacteristicLogDerivative::kMaxBodies,
                               CharacteristicLogDerivative::kMaxBodies>;

cd inverse(cd d) {  // without std::complex division's overflow guards
  const double r = 1.0 / std::norm(d);
  return {d.real() * r, -d.imag() * r};
}

constexpr int kMaxSweeps = 80;
}  // namespace

CharacteristicLogDerivative::CharacteristicLogDerivative(const ChainModel& m)
    : n_(m.n), M_(m.M), D_(m.D), K_(complex_stiffness(m)), G_(m.G.data(), m.G.data() + m.n) {
  for (const BodyModel& b : m.bodies) E_rem_.emplace_back(b.E_rem, b.E_rem_imag);
  // Modes are kept body by body (chain_model.hpp); the ranges below rely on it.
  first_mode_.assign(n_ + 1, 0);
  for (const FluidMode& md : m.modes) ++first_mode_[md.body + 1];
  for (int k = 0; k < n_; ++k) first_mode_[k + 1] += first_mode_[k];
  for (std::size_t l = 1; l < m.modes.size(); ++l)
    if (m.modes[l].body < m.modes[l - 1].body) throw std::logic_error("root tracking: modes not in body order");
  for (const FluidMode& md : m.modes) {
    const double w0 = m.bodies[md.body].omega;
    pole_.push_back(md.lambda_c() - w0);
    E_.push_back(md.E_c());
    E_lambda_.push_back(md.E_c() * md.lambda_c());
  }
  for (const BodyModel& b : m.bodies) omega_.push_back(b.omega);
}

CharacteristicLogDerivative::Result CharacteristicLogDerivative::eval(cd sigma, cd& value) const {
  if (sigma == cd(0)) return Result::undefined;
  const cd I(0, 1), inv = inverse(sigma), inv2 = inv * inv;
  // Phi and Phi' term by term as in characteristic.cpp; the fluid's sums share q_l = 1/(sigma - p_l).
  SmallMat Phi(n_, n_), dPhi(n_, n_);
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) {
      Phi(i, j) = M_(i, j) - I * D_(i, j) * inv - K_(i, j) * inv2;
      dPhi(i, j) = I * D_(i, j) * inv2 + 2.0 * K_(i, j) * inv2 * inv;
    }
  cd poles_sum = 0;
  for (int k = 0; k < n_; ++k) {
    const int l0 = first_mode_[k], l1 = first_mode_[k + 1];
    // The pole nearest sigma is taken out of row k: that row is multiplied by (sigma - p), which leaves
    // f unchanged (its factor prod (sigma - p_l) loses the same factor). Else, at a root that lies within rounding
    // of a weakly coupled mode's pole, 1/(sigma - p) from the product and -1/(sigma - p) from tr(Phi^{-1} Phi')
    // cancel to nothing but rounding, and the iteration cycles around the root instead of settling on it.
    // One pass in real arithmetic (the map's inner loop): the nearest pole so far is held aside, its terms added
    // only once a nearer one replaces it. Sums: sum_l q_l, sum_l E_l q_l (times sigma + omega_k0 below, the
    // same for all of the body's modes) and sum_l E_l lambda_l q_l^2.
    const double sr = sigma.real(), si = sigma.imag();
    int near = -1;
    double near_norm = std::numeric_limits<double>::infinity(), held_r = 0, held_i = 0;
    double qs_r = 0, qs_i = 0, eq_r = 0, eq_i = 0, elq_r = 0, elq_i = 0;
    auto add = [&](int l, double qr, double qi) {
      qs_r += qr, qs_i += qi;
      const cd e = E_[l], el = E_lambda_[l];
      eq_r += e.real() * qr - e.imag() * qi, eq_i += e.real() * qi + e.imag() * qr;
      const double q2r = qr * qr - qi * qi, q2i = 2 * qr * qi;
      elq_r += el.real() * q2r - el.imag() * q2i, elq_i += el.real() * q2i + el.imag() * q2r;
    };
    for (int l = l0; l < l1; ++l) {
      const double dr = sr - pole_[l].real(), di = si - pole_[l].imag(), nd = dr * dr + di * di;
      if (nd == 0 && near_norm == 0) return Result::undefined;  // two poles of one body on sigma
      const double r = nd > 0 ? 1.0 / nd : 0.0, qr = dr * r, qi = -di * r;
      if (nd < near_norm) {
        if (near >= 0) add(near, held_r, held_i);
        near = l, near_norm = nd, held_r = qr, held_i = qi;
      } else {
        add(l, qr, qi);
      }
    }
    poles_sum += cd(qs_r, qs_i);
    const cd fluid = E_rem_[k] + (sigma + omega_[k]) * cd(eq_r, eq_i), dfluid(elq_r, elq_i);
    Phi(k, k) += G_[k] * inv - fluid;
    dPhi(k, k) += -G_[k] * inv2 + dfluid;
    if (near >= 0) {  // row k times (sigma - p): its derivative by the product rule, then the near mode's own term
      const cd d = sigma - pole_[near];
      dPhi.row(k) = d * dPhi.row(k) + Phi.row(k);
      Phi.row(k) *= d;
      Phi(k, k) -= (sigma + omega_[k]) * E_[near];
      dPhi(k, k) -= E_[near];
    }
  }
  const Eigen::PartialPivLU<SmallMat> lu(Phi);
  if ((lu.matrixLU().diagonal().array() == cd(0)).any()) return Result::root;
  value = 2.0 * n_ * inv + poles_sum + lu.solve(dPhi).trace();
  return std::isfinite(value.real()) && std::isfinite(value.imag()) ? Result::value : Result::undefined;
}

namespace {

// The tolerance of an approximation z: 1e-13 of the oscillating roots' radius, 1e-14 relative for larger roots.
struct Tolerance {
  double absolute;
  double operator()(cd z) const { return std::max(absolute, 1e-14 * std::abs(z)); }
};

// Aberth sweeps until every approximation's Newton correction |f/f'| at its own point is below the tolerance.
// Returns "" or why not.
std::string aberth_sweeps(const CharacteristicLogDerivative& logd, Eigen::VectorXcd& z, const Tolerance& tol,
                          double radius, int& sweeps) {
  const int N = static_cast<int>(z.size());
  std::vector<char> done(N, 0);
  for (sweeps = 1; sweeps <= kMaxSweeps; ++sweeps) {
    bool moving = false;
    for (int j = 0; j < N; ++j) {
      if (done[j]) continue;
      cd L;
      const auto result = logd.eval(z[j], L);
      if (result == CharacteristicLogDerivative::Result::root) {  // Phi exactly singular: z_j is a root
        done[j] = 1;
        continue;
      }
      if (result == CharacteristicLogDerivative::Result::undefined) {
        // On sigma = 0 f'/f is not defined here: nudge off it (a true root there is found again).
        z[j] += cd(1, 1) * (1e-9 * radius);
        moving = true;
        continue;
      }
      const cd newton = inverse(L);
      if (std::abs(newton) <= tol(z[j])) {
        z[j] -= newton;
        done[j] = 1;
        continue;
      }
      cd repulsion = 0;
      for (int i = 0; i < N; ++i)
        if (i != j) repulsion += inverse(z[j] - z[i]);
      z[j] -= newton / (1.0 - newton * repulsion);
      if (!std::isfinite(z[j].real()) || !std::isfinite(z[j].imag())) return "an approximation left the finite plane";
      moving = true;  // done only once f/f' itself is below the tolerance at the new point (the check below needs it)
    }
    if (!moving) return "";
  }
  return "not converged in " + std::to_string(kMaxSweeps) + " sweeps";
}

// A disc of radius N |f/f'| about any point holds a zero of a polynomial of degree N (the Newton correction bound;
// e.g. Henrici, Applied and Computational Complex Analysis, vol. 1, 1974, §6.4). Every z_j was accepted with
// |f/f'| <= tol and then moved by that much, so a zero lies within (N + 1) tol of it; if the discs are pairwise
// disjoint, the N approximations sit on N distinct zeros, i.e. on all of them. Pairs are compared in the order of
// Re z, within reach only.
bool on_distinct_zeros(const Eigen::VectorXcd& z, const Tolerance& tol) {
  const int N = static_cast<int>(z.size());
  std::vector<double> apart(N);
  double reach = 0;
  for (int j = 0; j < N; ++j) reach = std::max(reach, apart[j] = 2.0 * (N + 1) * tol(z[j]));
  std::vector<int> order(N);
  for (int j = 0; j < N; ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return z[a].real() < z[b].real(); });
  for (int a = 0; a < N; ++a)
    for (int b = a + 1; b < N && z[order[b]].real() - z[order[a]].real() <= reach; ++b) {
      const int i = order[a], j = order[b];
      const double d = std::max(apart[i], apart[j]);
      if (std::norm(z[i] - z[j]) <= d * d) return false;
    }
  return true;
}

// The sum of the roots is -i tr B (sigma = -i mu): f and the first-order system are one problem.
bool sum_is_the_trace(const ChainModel& m, const Eigen::VectorXcd& z, double radius) {
  double size = 0;
  for (const cd x : z) size += std::abs(x);
  return std::abs(z.sum() - cd(0, -1) * first_order_trace(m)) <= 1e-10 * std::max(size, radius);
}

}  // namespace

TrackedRoots track_roots(const ChainModel& m, const Eigen::VectorXcd& start, double radius) {
  TrackedRoots t;
  t.sigma = start;
  if (m.n > CharacteristicLogDerivative::kMaxBodies) {
    t.why = "more than " + std::to_string(CharacteristicLogDerivative::kMaxBodies) + " bodies";
    return t;
  }
  // Its pole sums run row by row; a mode coupled to several bodies (a partially filled tank whose joint moves) is off
  // the diagonal: the eigen-solver takes such a point.
  for (const FluidMode& md : m.modes)
    if (!md.lever.empty() || md.lever_base != 0.0 || md.own != 1.0) {
      t.why = "a fluid mode coupled to several bodies";
      return t;
    }
  const CharacteristicLogDerivative logd(m);
  if (start.size() != logd.degree()) {
    t.why = "the number of roots changed";
    return t;
  }
  const Tolerance tol{1e-13 * radius};
  t.why = aberth_sweeps(logd, t.sigma, tol, radius, t.sweeps);
  if (!t.why.empty()) return t;
  if (!on_distinct_zeros(t.sigma, tol)) t.why = "two approximations on one root";
  else if (!sum_is_the_trace(m, t.sigma, radius)) t.why = "the roots' sum is not -i tr B";
  t.ok = t.why.empty();
  return t;
}

}  // namespace rc::rom
