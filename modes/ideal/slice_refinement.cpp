#include "slice_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace rc::modes {
namespace {

Cluster cluster_around_peak(const std::vector<Eigenpair>& pairs, double cluster_width) {
  const auto peak = std::max_element(pairs.begin(), pairs.end(),
                                     [](const Eigenpair& a, const Eigenpair& b) { return a.coupling.E < b.coupling.E; });
  const double delta = cluster_width * std::max(std::abs(peak->lambda), 0.1);
  Cluster c;
  double sum_lambda = 0;
  for (const auto& p : pairs) {
    if (std::abs(p.lambda - peak->lambda) > delta) continue;
    c.E += p.coupling.E;
    sum_lambda += p.coupling.E * p.lambda;
    c.residual = std::max(c.residual, p.residual);
    ++c.members;
  }
  c.lambda = c.E > 0 ? sum_lambda / c.E : peak->lambda;
  double var = 0;
  for (const auto& p : pairs)
    if (std::abs(p.lambda - peak->lambda) <= delta) var += p.coupling.E * (p.lambda - c.lambda) * (p.lambda - c.lambda);
  c.spread = c.E > 0 ? std::sqrt(var / c.E) : 0.0;
  return c;
}

}  // namespace

Cluster refine_node(const QuadraticEigenSolver& solver, const GaussNode& node, const ClusterSettings& settings) {
  Cluster c;
  double half = settings.slice_width * std::max(std::abs(node.lambda), 0.1);
  for (int attempt = 0; attempt <= settings.widenings; ++attempt, half *= 4) {
    // Stay inside (−2, 2), where every eigenvalue lies; D = 4 − λ² > 0 there.
    const double lo = std::max(node.lambda - half, -1.999999), hi = std::min(node.lambda + half, 1.999999);
    QepSolution sol = solver.solve_interval(lo, hi);
    if (sol.pairs.empty()) continue;
    c = cluster_around_peak(sol.pairs, settings.cluster_width);
    if (c.E >= 0.5 * node.E) break;  // the slice holds the mode the node stands for
  }
  return c;
}

std::vector<Cluster> refine_clusters(const PoincareForms& forms, const std::vector<GaussNode>& nodes,
                                     const ClusterSettings& settings,
                                     const std::function<void(std::size_t, std::size_t)>& progress,
                                     std::string* solver_description) {
  std::vector<Cluster> clusters;
  const QuadraticEigenSolver solver(forms, settings.qep);
  if (solver_description)
    *solver_description = "survey (Lanczos Gauss rule of the coupling measure) + SLEPc PEP stoar spectrum slicing "
                          "(MUMPS LDL^T inertia) around each node";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Cluster c = refine_node(solver, nodes[i], settings);
    if (progress) progress(i + 1, nodes.size());
    if (c.members == 0) continue;
    const bool duplicate = std::any_of(clusters.begin(), clusters.end(), [&](const Cluster& o) {
      return within_width(o.lambda, c.lambda, settings.cluster_width);
    });
    if (!duplicate) clusters.push_back(c);
  }
  return clusters;
}

}  // namespace rc::modes
