#include "mesh_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace rc::rom {
namespace {
constexpr double kSafetyFactor = 1.25;  // Roache's factor for a three-level study with the observed order
constexpr double kLeastOrder = 0.5;     // below it the differences are not taken as a converging sequence's
}  // namespace

double MeshErrorEstimate::relative() const {
  return growth != 0 ? error / std::abs(growth) : std::numeric_limits<double>::infinity();
}

MeshErrorEstimate mesh_error(const std::vector<std::complex<double>>& levels, double tolerance, double floor,
                             bool halving, double ratio) {
  if (levels.size() < 2) throw std::invalid_argument("mesh_error needs the root on two levels at least");
  MeshErrorEstimate e;
  const std::size_t L = levels.size() - 1;
  const auto g = [&](std::size_t l) { return -levels[l].imag(); };
  e.sigma = levels[L];
  e.growth = g(L);
  e.extrapolated = e.growth;
  const double d = g(L) - g(L - 1);
  e.error = halving ? std::abs(d) / (ratio - 1) : std::abs(d);
  if (L >= 2) {
    const double before = g(L - 1) - g(L - 2);
    const double p = std::log(std::abs(before) / std::abs(d)) / std::log(ratio);
    if (halving && std::isfinite(p) && p >= kLeastOrder) {
      const double gain = std::pow(ratio, p) - 1;
      e.order = p;
      e.asymptotic = true;
      e.error = kSafetyFactor * std::abs(d) / gain;
      e.extrapolated = e.growth + d / gain;
    } else if (d == 0 && before == 0) {
      e.asymptotic = true;  // every level the same rate: nothing left to extrapolate
    } else {
      e.error = std::max(std::abs(d), std::abs(before));
    }
  }
  e.converged = e.error <= tolerance * std::abs(e.growth) + floor;
  e.sign_settled = std::abs(e.growth) > e.error;
  return e;
}

std::string rate_with_error(const MeshErrorEstimate& e) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %.4g ± %.2g 1/s (%.2g %%)", e.growth > 0 ? "growth" : "decay", std::abs(e.growth),
                e.error, 100 * e.relative());
  return text;
}

}  // namespace rc::rom
