#include "root_confirmation.hpp"

#include "base_translation.hpp"
#include "characteristic.hpp"

#include "eigen_dense.hpp"
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rc::rom {
namespace {
using cd = std::complex<double>;

// The model without the listed bodies' modes and static-correction remainders: what (22) keeps of the chain when
// those tanks' fluid is given by R instead.
ChainModel without_tank_modes(const ChainModel& m, const std::vector<TankResponse>& tanks) {
  ChainModel out = m;
  const auto listed = [&](int body) {
    return std::any_of(tanks.begin(), tanks.end(), [&](const TankResponse& t) { return t.body == body; });
  };
  out.modes.erase(std::remove_if(out.modes.begin(), out.modes.end(), [&](const FluidMode& f) { return listed(f.body); }),
                  out.modes.end());
  for (const TankResponse& t : tanks) out.bodies[t.body].E_rem = out.bodies[t.body].E_rem_imag = 0;
  if (m.extended) {  // a free chain with a partially filled tank: its extended chain stripped alike
    ChainModel e = *m.extended;
    e.modes.erase(std::remove_if(e.modes.begin(), e.modes.end(), [&](const FluidMode& f) { return listed(f.body); }),
                  e.modes.end());
    for (const TankResponse& t : tanks) e.bodies[t.body].E_rem = e.bodies[t.body].E_rem_imag = 0;
    out.extended = std::make_shared<const ChainModel>(std::move(e));
  }
  return out;
}

// The tank's term of Φ (Kononov (22)): ρL⁵ s R on its body, or for a partially filled tank the form of R, R_fg, R_gg
// over its offset row (root_confirmation.hpp). Spin −ω mirrors the flow: R(s) -> conj(R(conj(s))).
void subtract_tank(Eigen::MatrixXcd& Phi, const TankResponse& t, double w, cd s) {
  const auto mirrored = [&](cd x) { return w > 0 ? x : std::conj(x); };
  if (!t.R_offset) {
    Phi(t.body, t.body) -= t.rho_L5 * s * mirrored(t.R(w > 0 ? s : std::conj(s)));
    return;
  }
  const std::array<cd, 3> r = t.R_offset(w > 0 ? s : std::conj(s));
  const cd R = mirrored(r[0]), R_fg = mirrored(r[1]), R_gg = mirrored(r[2]);
  const Eigen::VectorXcd g = t.offset_row.cast<cd>();
  Eigen::VectorXcd e = Eigen::VectorXcd::Zero(g.size());
  e[t.body] = 1;
  Phi -= t.rho_L5 * s * (R * e * e.transpose() + R_fg * (e * g.transpose() + g * e.transpose()) + R_gg * g * g.transpose());
}

// Phi_true(sigma) = Phi of the stripped model − diag(rho L^5 s R(s)) (Kononov (22); chain_model.cpp's mirror at
// negative spin: lambda_c -> -conj(lambda_c), E_c -> conj(E_c), i.e. R(s) -> conj(R(conj(s))).
// A free chain with a partially filled tank: on its extended chain, then reduced on the base (base_translation.hpp).
Eigen::MatrixXcd phi_true(const ChainModel& stripped, const std::vector<TankResponse>& tanks, cd sigma) {
  const bool extended = stripped.extended != nullptr;
  Eigen::MatrixXcd Phi = characteristic_matrix(extended ? *stripped.extended : stripped, sigma);
  for (const TankResponse& t : tanks) {
    const double w = stripped.bodies[t.body].omega;
    subtract_tank(Phi, t, w, (sigma + w) / w);
  }
  return extended ? reduce_on_base(Phi) : Phi;
}

// log det by LU (complex log: only exp of differences is used, so the branch does not matter); -inf when singular.
cd log_det(const Eigen::MatrixXcd& A) {
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(A);
  cd sum = 0;
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const cd u = lu.matrixLU()(i, i);
    if (u == cd(0)) return {-std::numeric_limits<double>::infinity(), 0};
    sum += std::log(u);
  }
  return sum;  // the permutation's sign drops out of every ratio below (same size, a sign at most)
}

bool finite(cd z) { return std::isfinite(z.real()) && std::isfinite(z.imag()); }
}  // namespace

Eigen::MatrixXcd characteristic_matrix_with(const ChainModel& m, const std::vector<TankResponse>& tanks, cd sigma) {
  return phi_true(without_tank_modes(m, tanks), tanks, sigma);
}

ConfirmedRoot confirm_root(const ChainModel& m, const std::vector<TankResponse>& tanks, cd start,
                           const ConfirmSettings& settings) {
  const ChainModel stripped = without_tank_modes(m, tanks);
  ConfirmedRoot r;
  r.start = r.sigma = start;
  const auto done = [&](cd step) { return std::abs(step) <= settings.tolerance * std::abs(r.sigma); };
  // Step 1: Newton with the table's dPhi/dsigma (f'/f = tr(Phi^-1 Phi'), root_newton.hpp) at Phi_true's value.
  Eigen::MatrixXcd Phi0 = phi_true(stripped, tanks, start);
  ++r.evaluations;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu0(Phi0);
  if ((lu0.matrixLU().diagonal().array() == cd(0)).any()) { r.converged = true; return r; }
  const cd trace = lu0.solve(characteristic_derivative(m, start)).trace();
  if (!finite(trace) || trace == cd(0)) { r.failure = "no Newton step from the table's root"; return r; }
  cd x0 = start, x1 = start - 1.0 / trace;
  cd l0 = log_det(Phi0);
  // Then secant steps on det Phi_true: x2 = x1 - (x1 - x0) / (1 - det0/det1).
  for (int k = 0; k < settings.max_steps; ++k) {
    r.sigma = x1;
    if (!finite(x1) || std::abs(x1 - start) > 0.5 * std::abs(start) + 1.0) {
      r.failure = "the iteration left the root's neighbourhood";
      return r;
    }
    if (done(x1 - x0)) { r.converged = true; return r; }
    const cd l1 = log_det(phi_true(stripped, tanks, x1));
    ++r.evaluations;
    if (std::isinf(l1.real()) && l1.real() < 0) { r.converged = true; return r; }  // exactly singular: on the root
    const cd ratio = std::exp(l0 - l1);
    if (!finite(ratio) || ratio == cd(1)) { r.failure = "the secant step is undefined"; return r; }
    const cd x2 = x1 - (x1 - x0) / (1.0 - ratio);
    x0 = x1;
    l0 = l1;
    x1 = x2;
  }
  r.sigma = x1;
  r.failure = "no convergence in " + std::to_string(settings.max_steps) + " steps";
  return r;
}

std::string root_text(std::complex<double> z) {
  std::ostringstream os;
  os << std::setprecision(10) << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "i";
  return os.str();
}

}  // namespace rc::rom
