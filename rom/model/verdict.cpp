#include "verdict.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace rc::rom {

Verdict verdict_of_roots(const Eigen::VectorXcd& sigma, bool dissipative, double neutral) {
  Verdict v;
  double radius = 0;
  for (Eigen::Index j = 0; j < sigma.size(); ++j) radius = std::max(radius, std::abs(sigma[j]));
  const double spectral_radius = radius;
  // A dissipative chain's tolerance on growth scales with its oscillating roots only: a root that decays
  // faster than it turns (Im sigma > |Re sigma|: overdamped joints, the heavily damped pseudo-modes of a
  // response-fit table at |sigma| ~ 1e4) says nothing about the accuracy of the slow near-real roots, and let
  // into the scale it made 1.7e-3 1/s of growth on a body root count as neutral (docs/rom.md, "Viscous tanks").
  if (dissipative) {
    double oscillating = 0;
    for (Eigen::Index j = 0; j < sigma.size(); ++j)
      if (sigma[j].imag() <= std::abs(sigma[j].real())) oscillating = std::max(oscillating, std::abs(sigma[j]));
    if (oscillating > 0) radius = oscillating;
  }
  v.radius = std::max(radius, 1e-300);
  v.tolerance = kRealTolerance * v.radius;
  v.roots = static_cast<int>(sigma.size());
  for (Eigen::Index j = 0; j < sigma.size(); ++j) {
    const double im = sigma[j].imag();
    v.margin = std::max(v.margin, std::abs(im));
    if (std::abs(im) > v.tolerance) ++v.nonreal;
  }
  if (!dissipative) {
    // Without friction Kononov's necessary condition: all roots real.
    v.growth = sigma.size() ? -std::numeric_limits<double>::infinity() : 0.0;
    for (Eigen::Index j = 0; j < sigma.size(); ++j) v.growth = std::max(v.growth, -sigma[j].imag());
    v.stable = v.margin <= v.tolerance;
    return v;
  }
  // With friction or a viscous tank roots move into Im sigma > 0 (decay), and stable means that none grows: the
  // tolerance is rounding, never physical growth (Kelvin–Tait–Chetaev: a gyroscopically stabilised chain with
  // dissipation grows, however slowly; docs/rom.md, "Verdict with dissipation").
  v.noise = kGrowthNoise * std::max(spectral_radius, 1e-300);
  v.growth = -std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < sigma.size(); ++j) {
    const bool at_neutral = neutral > 0 && std::min(std::abs(sigma[j] - neutral), std::abs(sigma[j] + neutral)) <= v.tolerance;
    if (std::abs(sigma[j]) <= v.tolerance || at_neutral) { ++v.at_zero; continue; }
    v.growth = std::max(v.growth, -sigma[j].imag());
    if (-sigma[j].imag() > v.noise) ++v.growing;
  }
  if (!std::isfinite(v.growth)) v.growth = 0;  // every root at sigma = 0
  v.margin = v.growth;                          // a dissipative chain's margin: its largest growth rate
  v.stable = v.growing == 0;
  return v;
}

}  // namespace rc::rom
