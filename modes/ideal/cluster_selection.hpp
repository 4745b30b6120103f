// Which clusters a table keeps (ModeSelection, docs/modes.md "Which clusters a table keeps"), for the mesh and
// the separable methods alike.
#pragma once

#include "cluster.hpp"

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

// The kept items (clusters, or the separable method's modes), E descending: at most max_clusters unless --modes
// asks for more. A table always has its heaviest one, even below the default threshold.
template <class Item>
std::vector<Item> select_clusters(std::vector<Item> items, const ModeSelection& sel, double sum_rule) {
  sort_by_energy(items);
  std::size_t keep = std::max(selected_count(items, sel, sum_rule), std::min<std::size_t>(1, items.size()));
  if (!sel.modes) keep = std::min<std::size_t>(keep, sel.max_clusters);
  items.resize(keep);
  return items;
}

}  // namespace rc::modes
