// Clusters by SLEPc spectrum slices around the survey's nodes (the `--clusters slices` method; the default
// is cluster_search.hpp).
//
// The discrete spectrum is dense, and an exact mode's E may be shared by several nearby discrete
// eigenpairs. A cluster is formed around a node θ of the spectral survey (spectral_survey.hpp):
//   1. SLEPc finds ALL eigenpairs in the slice |λ − θ| <= slice_width · max(|θ|, 0.1) (spectrum
//      slicing: none can be missed); the slice only has to contain the mode the node stands for. Nodes of
//      light modes can sit farther from their mode than the slice reaches (measured: 9e-4 at λ = 0.2 for
//      a cylinder), so while the cluster found carries less than half of the node's Gauss weight the
//      slice is widened ×4, at most `widenings` times;
//   2. the peak is the eigenpair of largest E in the slice;
//   3. the cluster is every eigenpair with |λ − λ_peak| <= δ = cluster_width · max(|λ_peak|, 0.1): E summed,
//      λ the E-weighted mean, and the E-weighted standard deviation of λ reported as its spread.
// δ is narrow because genuine neighbouring modes of small E can sit 1e-4 away (a cylinder of height 1
// has one 2.5e-4 from its third mode) while the discrete copies of one exact mode sit within ~1e-7 of
// each other at the default order 6.
// Clusters found twice (two survey nodes refining to the same peak) are merged. See docs/modes.md.
#pragma once

#include "cluster.hpp"
#include "spectral_survey.hpp"

#include <functional>
#include <vector>

namespace rc::modes {

// Refines one survey node into its cluster with `solver` (steps 1-3 above); no cluster (members = 0) if no
// slice held an eigenpair.
Cluster refine_node(const QuadraticEigenSolver& solver, const GaussNode& node, const ClusterSettings& settings);

// Refines the given survey nodes (in the order given) into clusters; `progress` (may be empty) is told
// after each node. Returns the clusters, duplicates merged, in the order of first appearance.
std::vector<Cluster> refine_clusters(const PoincareForms& forms, const std::vector<GaussNode>& nodes,
                                     const ClusterSettings& settings,
                                     const std::function<void(std::size_t done, std::size_t total)>& progress,
                                     std::string* solver_description = nullptr);

}  // namespace rc::modes
