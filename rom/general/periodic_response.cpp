#include "periodic_response.hpp"

#include "floquet.hpp"
#include "magnus.hpp"
#include "periodic_system.hpp"

#include "matrix_exponential.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <numbers>
#include <vector>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

// B and the moment's column b = input f at the three Gauss points of every step of a grid of T/N: the same for every
// frequency, so made once per grid (kept while they take less than kKeptBytes, else made again for each frequency).
class GaussSamples {
 public:
  GaussSamples(const GeneralChain& g, double s, int body, int steps) : g_(g), s_(s), body_(body), steps_(steps) {
    const double dim = static_cast<double>(periodic_matrix(g, 0, s).rows());
    keep_ = 3.0 * steps * dim * (dim + 2) * sizeof(double) < kKeptBytes;
    if (keep_) samples_.resize(3 * static_cast<std::size_t>(steps));
  }
  int steps() const { return steps_; }
  double h() const { return g_.period / steps_; }

  // h (B, b) at step j's Gauss point i.
  std::pair<Eigen::MatrixXd, Eigen::VectorXcd> at(int j, int i) {
    const std::size_t k = 3 * static_cast<std::size_t>(j) + static_cast<std::size_t>(i);
    if (keep_ && samples_[k].first.size() > 0) return samples_[k];
    const GeneralSystem sys = periodic_system(g_, (j + kMagnusNodes[i]) * h(), s_);
    std::pair<Eigen::MatrixXd, Eigen::VectorXcd> out{
        h() * sys.B, h() * (sys.input.col(2 * body_).cast<cd>() + cd(0, 1) * sys.input.col(2 * body_ + 1).cast<cd>())};
    if (keep_) samples_[k] = out;
    return out;
  }

 private:
  static constexpr double kKeptBytes = 512.0 * 1024 * 1024;
  const GeneralChain& g_;
  double s_;
  int body_, steps_;
  bool keep_ = false;
  std::vector<std::pair<Eigen::MatrixXd, Eigen::VectorXcd>> samples_;
};

// The augmented system's step exponential exp(Ω), Ω the Magnus exponent of [[h(B − iΩ), h b], [0, 0]].
Eigen::MatrixXcd augmented_step(GaussSamples& samples, int j, double Omega) {
  Eigen::MatrixXcd A[3];
  for (int i = 0; i < 3; ++i) {
    const auto [hB, hb] = samples.at(j, i);
    const Eigen::Index dim = hB.rows();
    A[i] = Eigen::MatrixXcd::Zero(dim + 1, dim + 1);
    A[i].topLeftCorner(dim, dim) = hB.cast<cd>();
    A[i].topLeftCorner(dim, dim).diagonal().array() -= cd(0, Omega * samples.h());
    A[i].topRightCorner(dim, 1) = hb;
  }
  return rc::matrix_exponential(magnus_exponent(A[0], A[1], A[2]));
}

// Singular values of I − e^{−iΩT}Φ below this fraction of the largest count as zero; a least-squares residual above
// kResonantResidual of the right-hand side then marks a resonance.
constexpr double kNeutralThreshold = 1e-10;
constexpr double kResonantResidual = 1e-6;

struct Steady {
  enum Kind { found, resonant, aliased } kind = found;
  std::vector<Eigen::VectorXcd> p;  // p(t_j) on the grid, j = 0 .. N − 1
};

// The T-periodic p of the steady response at Ω: w by one period of augmented steps from p = 0, then p(0) from the
// monodromy, then p along the grid (the steps kept from the first pass while they take less than 512 MB).
//
// A neutral Floquet motion whose multiplier e^{−iΩT} meets makes I − e^{−iΩT}Φ singular. When the moment drives it
// (the least-squares residual stays) the response grows without bound: `resonant`. When it does not — a free chain's
// drift at frequency 0 aliased to σ = kν or −2ω0 + kν — p is determined only up to that motion: `aliased`, and the
// caller takes the limit from either side.
Steady steady_response(GaussSamples& samples, const Eigen::MatrixXd& monodromy, double Omega) {
  const int N = samples.steps();
  const Eigen::Index dim = monodromy.rows();
  const bool keep = 16.0 * N * static_cast<double>((dim + 1) * (dim + 1)) < 512.0 * 1024 * 1024;
  std::vector<Eigen::MatrixXcd> kept(keep ? static_cast<std::size_t>(N) : 0);
  const auto step = [&](int j) -> Eigen::MatrixXcd {
    if (!keep) return augmented_step(samples, j, Omega);
    Eigen::MatrixXcd& e = kept[static_cast<std::size_t>(j)];
    if (e.size() == 0) e = augmented_step(samples, j, Omega);
    return e;
  };
  Eigen::VectorXcd w = Eigen::VectorXcd::Zero(dim + 1);
  w[dim] = 1;
  for (int j = 0; j < N; ++j) w = step(j) * w;
  const double T = samples.h() * N;
  const Eigen::MatrixXcd lhs =
      Eigen::MatrixXcd::Identity(dim, dim) - std::exp(cd(0, -Omega * T)) * monodromy.cast<cd>();
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXcd> cod;
  cod.setThreshold(kNeutralThreshold);
  cod.compute(lhs);
  Steady out;
  Eigen::VectorXcd y(dim + 1);
  y.head(dim) = cod.solve(w.head(dim));
  y[dim] = 1;
  if (!y.allFinite() || (lhs * y.head(dim) - w.head(dim)).norm() > kResonantResidual * w.head(dim).norm()) {
    out.kind = Steady::resonant;
    return out;
  }
  if (cod.rank() < dim) {
    out.kind = Steady::aliased;
    return out;
  }
  for (int j = 0; j < N; ++j) {
    out.p.push_back(y.head(dim));
    y = step(j) * y;
  }
  return out;
}

// At an aliased Ω the response is continuous: Richardson's limit of the means m(δ) of those at Ω ± δ,
// (4 m(δ) − m(2δ))/3 with δ = 1e-5 ν (error O(δ⁴), and rounding over δT).
Steady steady_response_or_limit(GaussSamples& samples, const Eigen::MatrixXd& monodromy, double Omega) {
  Steady st = steady_response(samples, monodromy, Omega);
  if (st.kind != Steady::aliased) return st;
  const double delta = 1e-5 * 2 * std::numbers::pi / (samples.h() * samples.steps());
  const double offsets[4] = {-delta, delta, -2 * delta, 2 * delta}, weights[4] = {2.0 / 3, 2.0 / 3, -1.0 / 6, -1.0 / 6};
  Steady limit;
  for (int i = 0; i < 4; ++i) {
    const Steady near = steady_response(samples, monodromy, Omega + offsets[i]);
    if (near.kind != Steady::found) return near;
    if (i == 0) limit.p.assign(near.p.size(), Eigen::VectorXcd::Zero(near.p[0].size()));
    for (std::size_t j = 0; j < near.p.size(); ++j) limit.p[j] += weights[i] * near.p[j];
  }
  return limit;
}

// Steps a period at Ω: the settled count, doubled while h|Ω| is beyond the h ρ it was settled at.
int steps_at(const FloquetSteps& settled, double Omega) {
  int n = settled.per_period;
  while (n < (1 << 20) && std::abs(Omega) > settled.radius * n / settled.per_period) n *= 2;
  return n;
}

}  // namespace

GeneralFrequencyResponse periodic_frequency_response(const GeneralChain& g, int body, double from, double to,
                                                     int steps) {
  const FloquetSteps settled = floquet_steps(g);
  const double s = settled.s;
  GeneralFrequencyResponse r;
  r.body = body;
  r.tilt.resize(steps, g.n);
  r.mirror.resize(steps, g.n);
  r.sideband.resize(steps, g.n);
  std::map<int, std::pair<GaussSamples, Eigen::MatrixXd>> grids;  // per steps a period: samples and monodromy
  const cd I(0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < steps; ++i) {
    const double sigma = from + (to - from) * i / (steps - 1);
    r.sigma.push_back(sigma);
    const double Omega = sigma + g.spin;
    const int N = steps_at(settled, Omega);
    r.steps_per_period = std::max(r.steps_per_period, N);
    auto grid = grids.find(N);
    if (grid == grids.end())
      grid = grids.try_emplace(N, GaussSamples(g, s, body, N), magnus_transition(g, s, 0, g.period / N, N)).first;
    const Steady st = steady_response_or_limit(grid->second.first, grid->second.second, Omega);
    if (st.kind != Steady::found) {  // exactly at a root
      ++r.singular;
      r.tilt.row(i).setConstant(cd(nan, 0));
      r.mirror.row(i).setConstant(cd(nan, 0));
      r.sideband.row(i).setConstant(nan);
      continue;
    }
    for (int k = 0; k < g.n; ++k) {
      std::vector<cd> a, b;
      for (const Eigen::VectorXcd& p : st.p) {
        const cd qx = p[2 * k] / s, qy = p[2 * k + 1] / s;
        a.push_back(0.5 * (qx - I * qy));
        b.push_back(0.5 * std::conj(qx + I * qy));
      }
      const auto mean = [](const std::vector<cd>& x) {
        cd m = 0;
        for (const cd v : x) m += v;
        return m / static_cast<double>(x.size());
      };
      const cd A_plus = mean(a), A_minus = mean(b);
      double rest = 0;
      for (std::size_t j = 0; j < a.size(); ++j) rest += std::norm(a[j] - A_plus) + std::norm(b[j] - A_minus);
      r.tilt(i, k) = A_plus;
      r.mirror(i, k) = A_minus;
      r.sideband(i, k) = std::sqrt(rest / static_cast<double>(a.size()));
    }
  }
  mark_resonances(g, from, to, r);
  return r;
}

}  // namespace rc::rom
