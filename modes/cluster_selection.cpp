#include "cluster_selection.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace rc::modes {

void validate(const ModeSelection& s) {
  if (s.modes && *s.modes < 1) throw std::runtime_error(fmt::format("--modes must be at least 1 (got {})", *s.modes));
  if (s.coverage && !(*s.coverage > 0 && *s.coverage <= 1))
    throw std::runtime_error(fmt::format("--coverage must be in (0, 1] (got {})", *s.coverage));
}

std::vector<Cluster> select_clusters(std::vector<Cluster> clusters, const ModeSelection& sel, double sum_rule) {
  sort_by_energy(clusters);
  clusters.resize(std::max(selected_count(clusters, sel, sum_rule), std::min<std::size_t>(1, clusters.size())));
  return clusters;
}

void add_modes(ModeTable& t, const std::vector<Cluster>& clusters, double sum_rule) {
  double kept = 0;
  for (const auto& c : clusters) {
    t.lambda.push_back(c.lambda);
    t.kappa.push_back(2 / c.lambda);
    t.E.push_back(c.E);
    t.a.push_back(std::sqrt(c.E / 2));
    t.N2.push_back(1.0);
    t.residual.push_back(c.residual);
    t.spread.push_back(c.spread);
    t.members.push_back(c.members);
    kept += c.E;
  }
  t.coverage = sum_rule > 0 ? kept / sum_rule : 1.0;
}

}  // namespace rc::modes
