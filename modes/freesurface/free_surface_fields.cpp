#include "free_surface_fields.hpp"

#include "cluster_fields.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

// The table's row λ is a pair's λ as computed (one pair per row): found by equality up to rounding.
const PartialFillPair& pair_of(const PartialFillSpectrum& s, double lambda) {
  const PartialFillPair* best = nullptr;
  for (const auto& p : s.pairs)
    if (!best || std::abs(p.lambda - lambda) < std::abs(best->lambda - lambda)) best = &p;
  if (!best || std::abs(best->lambda - lambda) > 1e-12 * std::max(1.0, std::abs(lambda)) || best->pressure.empty())
    throw std::runtime_error(fmt::format("fields: no eigenvector for the row at lambda = {:.12g}", lambda));
  return *best;
}

}  // namespace

ModeFields free_surface_fields(const FESpace& space, const PartialFillSpectrum& s, const ModeTable& table) {
  std::vector<WeightedPressure> rows;
  for (std::size_t row = 0; row < table.size(); ++row) {
    const PartialFillPair& pair = pair_of(s, table.lambda[row]);
    const double l = pair.lambda, D = 4 - l * l;
    if (!(pair.coupling.norm > 0)) throw std::runtime_error("fields: a row's pair has no energy");
    // W = ±W̃/‖W̃‖ with Ṽ = λ D V(p). The sign as a filled cavity's field has it (cluster_fields.hpp: a ≥ 0 with
    // coupling.hpp's a = −π(f1·p/(2 − λ) + f2·p/λ)), whose sign is opposite to free_surface_coupling.hpp's ⟨U_c, W⟩:
    // so that a field is continuous as the fill goes to 1 (the sphere's rigid turn is then the spin-over mode's).
    const double weight = (pair.coupling.a < 0 ? 1 : -1) * l * D / pair.coupling.norm;
    rows.push_back({l, &pair.pressure, weight, std::abs(pair.coupling.a), pair.coupling.E});
  }
  return weighted_mode_fields(space, rows);
}

}  // namespace rc::modes
