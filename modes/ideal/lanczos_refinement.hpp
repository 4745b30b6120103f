// Clusters by shift-and-invert Lanczos Gauss rules around the survey's nodes (the default `--clusters
// lanczos` method; `slices` is slice_refinement.hpp).
//
// For a survey node θ (spectral_survey.hpp), a Lanczos process on (A − σ)⁻¹ with σ just off θ
// (shift_invert_survey.hpp) runs until every node of its rule heavier than the floor within
// |λ − θ| <= slice_width · max(|θ|, 0.1) has settled. The eigenvalue the survey node stands for is then the
// one nearest the shift, which a shift-and-invert Krylov space resolves first (measured on the 2h/a = 2
// cylinder: 10 steps, 0.07 s with the factorisation, against 0.2-1.5 s for a SLEPc spectrum slice). The
// cluster is the heaviest settled node in that window merged with the settled nodes within the cluster
// width of it. As for slices, while the cluster carries less than half of the node's Gauss weight the
// window is widened ×4, at most `widenings` times.
#pragma once

#include "cluster.hpp"
#include "lanczos.hpp"
#include "shift_invert_survey.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::modes {

// A node that did not settle (solver trouble at that node; the message says where and how far it got).
struct UnsettledNode : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class LanczosRefinement {
 public:
  // w: P_H(e1 × r); mass = A_f − J_zh.
  LanczosRefinement(const VelocitySpace& V, const PoincareForms& forms, const Eigen::VectorXd& w, double mass,
                    const ClusterSettings& settings);
  // The cluster the node stands for; members = 0 if no node settled in the window. Throws UnsettledNode if
  // a node of the window with at least 1 % of the node's weight does not settle (after one run re-shifted
  // to it).
  Cluster refine(const GaussNode& node) const;

  // Clusters at least `floor` heavy strictly between two known clusters at λ = a and b (same sign): one
  // run shifted to the geometric middle of the gap, watching the gap without the cluster width at its ends,
  // and one re-shifted run per heavy node that did not settle. Nodes that still do not settle are dropped:
  // the gap search only adds what the survey missed.
  std::vector<Cluster> search_gap(double a, double b, double floor) const;

 private:
  ShiftInvertSurvey sil_;
  double mass_;
  ClusterSettings settings_;
};

// Refines the nodes (in the order given); duplicates merged, in order of first appearance. A node that does
// not settle is refined by `fallback` instead (SLEPc slices, which need no settling), counted in `fallbacks`.
std::vector<Cluster> refine_clusters_lanczos(const LanczosRefinement& refinement, const std::vector<GaussNode>& nodes,
                                             double cluster_width,
                                             const std::function<void(std::size_t done, std::size_t total)>& progress,
                                             const std::function<Cluster(const GaussNode&)>& fallback, int& fallbacks);

// Merges nodes whose λ differ by at most width · max(|λ|, 0.1) from their neighbour; sorted by λ.
std::vector<Cluster> merge_nodes(std::vector<SettledNode> nodes, double width);

}  // namespace rc::modes
