#include "floquet.hpp"

#include "balancing.hpp"
#include "magnus.hpp"
#include "periodic_system.hpp"
#include "verdict.hpp"

#include "matrix_exponential.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

// One sixth-order Magnus step over [t, t + h] (magnus.hpp).
Eigen::MatrixXd magnus_step(const GeneralChain& g, double s, double t, double h, Eigen::MatrixXd* mean = nullptr) {
  const Eigen::MatrixXd A1 = h * periodic_matrix(g, t + kMagnusNodes[0] * h, s);
  const Eigen::MatrixXd A2 = h * periodic_matrix(g, t + kMagnusNodes[1] * h, s);
  const Eigen::MatrixXd A3 = h * periodic_matrix(g, t + kMagnusNodes[2] * h, s);
  if (mean) *mean += (5 * A1 + 8 * A2 + 5 * A3) / 18;  // Gauss's rule: ∫B over the step
  return rc::matrix_exponential(magnus_exponent(A1, A2, A3));
}

Eigen::MatrixXd monodromy(const GeneralChain& g, double s, int steps, Eigen::MatrixXd& mean) {
  const double h = g.period / steps;
  Eigen::MatrixXd phi;
  mean.setZero();
  for (int j = 0; j < steps; ++j) {
    const Eigen::MatrixXd step = magnus_step(g, s, j * h, h, &mean);
    phi = j == 0 ? step : (step * phi).eval();
  }
  mean /= g.period;
  return phi;
}

Eigen::VectorXcd eigenvalues(Eigen::MatrixXd A, const std::string& what) {
  balance_in_place(A);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  if (es.info() != Eigen::Success) throw std::runtime_error(what + ": the eigen-solver did not converge");
  return es.eigenvalues();
}

// The exponents' principal values: Re σ = arg μ / T in (−Ω/2, Ω/2], Im σ = −ln|μ|/T.
std::vector<cd> principal_exponents(const Eigen::VectorXcd& mu, double T) {
  std::vector<cd> sigma;
  // A multiplier below 1e-300 (a mode damped by more than 690 e-foldings a period) is held there.
  for (const cd m : mu) sigma.emplace_back(std::arg(m) / T, -std::log(std::max(std::abs(m), 1e-300)) / T);
  return sigma;
}

// x − a wrapped into (−Ω/2, Ω/2].
double wrapped(double x, double a, double omega) { return x - a - omega * std::round((x - a) / omega); }

// Greedy pairing (smallest distance first) of two equally long lists of exponents, Re compared modulo Ω.
std::vector<int> pair_up(const std::vector<cd>& a, const std::vector<cd>& b, double omega) {
  struct Pair { double d; int i, j; };
  std::vector<Pair> pairs;
  for (int i = 0; i < static_cast<int>(a.size()); ++i)
    for (int j = 0; j < static_cast<int>(b.size()); ++j)
      pairs.push_back({std::hypot(wrapped(a[i].real(), b[j].real(), omega), a[i].imag() - b[j].imag()), i, j});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.d < y.d; });
  std::vector<int> of(a.size(), -1);
  std::vector<bool> taken(b.size(), false);
  for (const Pair& p : pairs)
    if (of[p.i] < 0 && !taken[p.j]) { of[p.i] = p.j; taken[p.j] = true; }
  return of;
}

// The monodromy's eigenvalues are good to about ε‖Φ‖: a multiplier below 1e-6 of the largest (a root decaying by
// ln 10⁶ = 13.8 more e-foldings a period than the fastest-growing one) may be known to less than 1e-10 of itself,
// and the steps are not doubled for its sake.
constexpr double kResolvedRange = 13.815510557964274;  // ln 10⁶

bool resolved(cd sigma, double fastest_growth, double period) {
  return -sigma.imag() >= fastest_growth - kResolvedRange / period;
}

double fastest_growth(const std::vector<cd>& a) {
  double g = -std::numeric_limits<double>::infinity();
  for (const cd x : a) g = std::max(g, -x.imag());
  return g;
}

// Each root's move from its partner in `b`.
std::vector<double> moves(const std::vector<cd>& a, const std::vector<cd>& b, double omega) {
  const std::vector<int> of = pair_up(a, b, omega);
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    d[i] = std::hypot(wrapped(a[i].real(), b[of[i]].real(), omega), a[i].imag() - b[of[i]].imag());
  return d;
}

double spectral_radius(const Eigen::MatrixXd& B) {
  double r = 0;
  for (const cd e : eigenvalues(B, "the periodic chain at t = 0")) r = std::max(r, std::abs(e));
  return r;
}

constexpr int kMostSteps = 1 << 16;  // Magnus steps a period

struct Settled {
  Eigen::MatrixXd phi;        // the last monodromy
  std::vector<cd> exponents;  // principal values
  Eigen::MatrixXd mean;       // B averaged over the period
  std::vector<double> moves;  // each root's move from the monodromy with half the steps (rad/s)
  int steps = 0;
  double error = 0, radius = 0, s = 1;  // error: the largest move of a resolved root
};

// Doubles the steps per period until two monodromies' resolved exponents agree to 1e-10 of the spectral radius.
Settled settle(const GeneralChain& g) {
  Settled out;
  out.s = build_general_system(turned_chain(g, 0)).s;
  out.radius = std::max(spectral_radius(periodic_matrix(g, 0, out.s)), 2 * M_PI / g.period);
  const double omega = 2 * M_PI / g.period;
  // The Magnus series converges for h‖B‖ < π: start at h ρ ≈ 0.5.
  int steps = 16;
  while (steps < 2 * out.radius * g.period && steps <= kMostSteps / 2) steps *= 2;
  if (steps > kMostSteps / 2) {
    std::ostringstream os;
    os << "the spins differ by only " << omega << " rad/s: a period (" << g.period << " s) spans " << out.radius * g.period
       << " radians of the chain's fastest motion, more than 2^16 Magnus steps resolve; give the bodies the same spin "
          "or spins further apart";
    throw std::runtime_error(os.str());
  }
  const Eigen::Index dim = periodic_matrix(g, 0, out.s).rows();
  Eigen::MatrixXd mean(dim, dim);
  std::vector<cd> last = principal_exponents(eigenvalues(monodromy(g, out.s, steps, mean), "the monodromy"), g.period);
  for (steps *= 2; steps <= kMostSteps; steps *= 2) {
    out.phi = monodromy(g, out.s, steps, mean);
    const std::vector<cd> now = principal_exponents(eigenvalues(out.phi, "the monodromy"), g.period);
    out.moves = moves(now, last, omega);
    out.error = 0;
    const double fastest = fastest_growth(now);
    for (std::size_t i = 0; i < now.size(); ++i)
      if (resolved(now[i], fastest, g.period)) out.error = std::max(out.error, out.moves[i]);
    out.exponents = now;
    out.mean = mean;
    out.steps = steps;
    if (out.error <= 1e-10 * out.radius) return out;
    last = now;
  }
  throw std::runtime_error("the periodic chain's monodromy did not settle: its roots moved by " + std::to_string(out.error) +
                           " rad/s from 2^15 to 2^16 Magnus steps a period (more than 1e-10 of the spectral radius " +
                           std::to_string(out.radius) + " rad/s)");
}

// Each principal exponent in the branch nearest the averaged chain's root it pairs with.
std::vector<cd> unfolded(const std::vector<cd>& exponents, const Eigen::MatrixXd& mean, double period) {
  const double omega = 2 * M_PI / period;
  std::vector<cd> averaged;
  for (const cd mu : eigenvalues(mean, "the averaged chain")) averaged.emplace_back(mu.imag(), -mu.real());
  const std::vector<int> of = pair_up(exponents, averaged, omega);
  std::vector<cd> out;
  for (std::size_t i = 0; i < exponents.size(); ++i) {
    const double a = averaged[of[i]].real();
    out.emplace_back(a + wrapped(exponents[i].real(), a, omega), exponents[i].imag());
  }
  return out;
}

}  // namespace

Eigen::MatrixXd magnus_transition(const GeneralChain& g, double s, double t0, double h, int steps) {
  const Eigen::Index dim = periodic_matrix(g, t0, s).rows();
  Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(dim, dim);
  for (int j = 0; j < steps; ++j) phi = (magnus_step(g, s, t0 + j * h, h) * phi).eval();
  return phi;
}

PeriodicPropagator::PeriodicPropagator(const GeneralChain& g, double s, int steps_per_period, const Eigen::VectorXd& y0)
    : g_(g), s_(s), h_(g.period / steps_per_period), steps_(static_cast<std::size_t>(steps_per_period)), y_(y0) {}

Eigen::VectorXd PeriodicPropagator::at(double t) {
  const long n = static_cast<long>(steps_.size());
  while ((grid_ + 1) * h_ <= t) {
    Eigen::MatrixXd& step = steps_[static_cast<std::size_t>(grid_ % n)];
    if (step.size() == 0) step = magnus_step(g_, s_, static_cast<double>(grid_ % n) * h_, h_);
    y_ = step * y_;
    ++grid_;
  }
  const double rest = t - grid_ * h_;
  if (rest <= 1e-14 * h_) return y_;
  return magnus_step(g_, s_, static_cast<double>(grid_ % n) * h_, rest) * y_;
}

FloquetSteps floquet_steps(const GeneralChain& g) {
  const Settled st = settle(g);
  return {st.steps, st.s, st.radius};
}

FloquetModes floquet_modes(const GeneralChain& g) {
  const Settled st = settle(g);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(st.phi, true);
  if (es.info() != Eigen::Success) throw std::runtime_error("the monodromy: the eigen-solver did not converge");
  return {unfolded(principal_exponents(es.eigenvalues(), g.period), st.mean, g.period), es.eigenvectors()};
}

GeneralSpectrum floquet_spectrum(const GeneralChain& g) {
  const Settled st = settle(g);
  const std::vector<cd> roots = unfolded(st.exponents, st.mean, g.period);
  GeneralSpectrum sp;
  Eigen::VectorXcd sigma(static_cast<Eigen::Index>(roots.size()));
  for (std::size_t i = 0; i < roots.size(); ++i) {
    sigma[static_cast<Eigen::Index>(i)] = roots[i];
    sp.roots.push_back(roots[i]);
  }
  std::sort(sp.roots.begin(), sp.roots.end(), [](cd a, cd b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
  });
  sp.verdict = verdict_of_roots(sigma, g.dissipative);
  if (g.dissipative && sp.verdict.noise < 10 * st.error) {
    sp.verdict.noise = 10 * st.error;
    sp.verdict.growing = 0;
    for (Eigen::Index j = 0; j < sigma.size(); ++j)
      if (std::abs(sigma[j]) > sp.verdict.tolerance && -sigma[j].imag() > sp.verdict.noise) ++sp.verdict.growing;
    sp.verdict.stable = sp.verdict.growing == 0;
  }
  for (const double d : st.moves) sp.floquet_unresolved += d > 1e-9 * st.radius;
  sp.floquet_steps = st.steps;
  sp.floquet_error = st.error;
  return sp;
}

}  // namespace rc::rom
