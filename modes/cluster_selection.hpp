// Which clusters a table keeps (ModeSelection, docs/modes.md "Which clusters a table keeps") and how kept
// clusters become the /modes rows of a table — shared by the mesh and the separable methods.
#pragma once

#include "cluster.hpp"
#include "mode_table.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace rc::modes {

// Which clusters a table keeps:
//   modes = N     the N clusters of largest E;
//   coverage = c  clusters in order of E until their E sums to c (A_f − J_zh);
//   neither       every cluster whose E is at least default_threshold (A_f − J_zh), which keeps every
//                 mode that moves a stability boundary by more than ~0.1 %.
struct ModeSelection {
  std::optional<int> modes;
  std::optional<double> coverage;
  double default_threshold = 1e-3;
  int max_clusters = 60;
  double geostrophic_cutoff = 0.02;  // no cluster is sought with |λ| below this (the λ ≈ 0 accumulation)
};

// Throws std::runtime_error (one line) for --modes < 1 or --coverage outside (0, 1].
void validate(const ModeSelection& selection);

template <class Item>
void sort_by_energy(std::vector<Item>& items) {
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.E > b.E; });
}

// How many of the items, sorted by E descending, the selection keeps.
template <class Item>
std::size_t selected_count(const std::vector<Item>& items, const ModeSelection& sel, double sum_rule) {
  if (sel.modes) return std::min<std::size_t>(items.size(), *sel.modes);
  std::size_t keep = 0;
  if (sel.coverage) {
    for (double sum = 0; keep < items.size() && sum < *sel.coverage * sum_rule;) sum += items[keep++].E;
    return keep;
  }
  while (keep < items.size() && items[keep].E >= sel.default_threshold * sum_rule) ++keep;
  return keep;
}

// The kept clusters, E descending. A table always has its heaviest cluster, even below the default threshold.
std::vector<Cluster> select_clusters(std::vector<Cluster> clusters, const ModeSelection& sel, double sum_rule);

// Appends the clusters as /modes rows (κ, λ, E, a = sqrt(E/2) with N² = 1, residual, spread, members) and
// sets the table's coverage Σ E / sum_rule.
void add_modes(ModeTable& table, const std::vector<Cluster>& clusters, double sum_rule);

}  // namespace rc::modes
