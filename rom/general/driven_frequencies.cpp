#include "driven_frequencies.hpp"

#include "floquet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rc::rom {
namespace {

using cd = std::complex<double>;

// The periodic part p(t_j) = e^{−iσt_j} y(t_j) of the Floquet solution through y(0) = v, on the grid t_j = jT/N.
std::vector<Eigen::VectorXcd> periodic_part(const GeneralChain& g, const FloquetSteps& steps, cd sigma,
                                            const Eigen::VectorXcd& v) {
  PeriodicPropagator re(g, steps.s, steps.per_period, v.real()), im(g, steps.s, steps.per_period, v.imag());
  std::vector<Eigen::VectorXcd> p;
  for (int j = 0; j < steps.per_period; ++j) {
    const double t = g.period * j / steps.per_period;
    const Eigen::VectorXcd y = re.at(t).cast<cd>() + cd(0, 1) * im.at(t).cast<cd>();
    p.push_back(std::exp(cd(0, -1) * sigma * t) * y);
  }
  return p;
}

// Body k's fluid rows of the state (s q, Q̇, Z): each of its modes' (Re z, Im z).
std::vector<int> fluid_rows(const GeneralChain& g, int body) {
  std::vector<int> rows;
  const int first = 2 * g.n + g.dim_q();
  for (int l = 0; l < g.n_modes(); ++l)
    if (g.modes[static_cast<std::size_t>(l)].body == body) rows.insert(rows.end(), {first + 2 * l, first + 2 * l + 1});
  return rows;
}

// The mean square of each harmonic j (−N/2 ≤ j < N/2) of p's rows `rows`.
std::vector<std::pair<int, double>> harmonic_shares(const std::vector<Eigen::VectorXcd>& p, const std::vector<int>& rows) {
  const int N = static_cast<int>(p.size());
  std::vector<std::pair<int, double>> out;
  for (int j = -N / 2; j < N / 2; ++j) {
    double power = 0;
    for (const int r : rows) {
      cd sum = 0;
      for (int i = 0; i < N; ++i) sum += p[static_cast<std::size_t>(i)][r] * std::polar(1.0, -2 * std::numbers::pi * j * i / N);
      power += std::norm(sum / static_cast<double>(N));
    }
    out.emplace_back(j, power);
  }
  return out;
}

}  // namespace

std::vector<std::vector<cd>> driven_frequencies(const GeneralChain& g, const std::vector<cd>& roots, std::ostream& log) {
  std::vector<std::vector<cd>> out(static_cast<std::size_t>(g.n));
  std::vector<std::vector<int>> rows;
  for (int k = 0; k < g.n; ++k) rows.push_back(fluid_rows(g, k));
  if (!g.periodic()) {
    for (int k = 0; k < g.n; ++k)
      if (!rows[static_cast<std::size_t>(k)].empty()) out[static_cast<std::size_t>(k)] = roots;
    return out;
  }
  const FloquetModes modes = floquet_modes(g);
  const FloquetSteps steps = floquet_steps(g);
  const double nu = 2 * std::numbers::pi / g.period;
  for (const cd sigma : roots) {
    // The monodromy's eigenvector of the exponent nearest σ (modulo ν).
    std::size_t best = 0;
    double gap = 1e300;
    for (std::size_t i = 0; i < modes.roots.size(); ++i) {
      double re = modes.roots[i].real() - sigma.real();
      re -= nu * std::round(re / nu);
      const double d = std::hypot(re, modes.roots[i].imag() - sigma.imag());
      if (d < gap) gap = d, best = i;
    }
    const cd exponent = modes.roots[best];
    const std::vector<Eigen::VectorXcd> p =
        periodic_part(g, steps, exponent, modes.vectors.col(static_cast<Eigen::Index>(best)));
    log << "  root " << sigma.real() << (sigma.imag() < 0 ? " - " : " + ") << std::abs(sigma.imag()) << "i:";
    for (int k = 0; k < g.n; ++k) {
      if (rows[static_cast<std::size_t>(k)].empty()) continue;
      std::vector<std::pair<int, double>> shares = harmonic_shares(p, rows[static_cast<std::size_t>(k)]);
      double total = 0;
      for (const auto& [j, w] : shares) total += w;
      std::sort(shares.begin(), shares.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
      double left = total;
      int kept = 0;
      log << " body " << k + 1 << " at";
      for (const auto& [j, w] : shares) {
        if (kept == kMostHarmonics || w < kHarmonicShare * total) break;
        out[static_cast<std::size_t>(k)].push_back(exponent + static_cast<double>(j) * nu);
        left -= w;
        ++kept;
        log << " " << (exponent.real() + j * nu);
      }
      log << " rad/s (" << (total > 0 ? std::max(left, 0.0) / total : 0.0) << " of the motion left out);";
    }
    log << std::endl;
  }
  return out;
}

}  // namespace rc::rom
