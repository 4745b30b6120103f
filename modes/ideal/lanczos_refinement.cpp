#include "lanczos_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace rc::modes {

namespace {

const SettledNode* heaviest_unsettled(const ShiftInvertRule& rule, double at_least) {
  const SettledNode* best = nullptr;
  for (const auto& n : rule.unsettled)
    if (n.E >= at_least && (!best || n.E > best->E)) best = &n;
  return best;
}

}  // namespace

std::vector<Cluster> merge_nodes(std::vector<SettledNode> nodes, double width) {
  std::sort(nodes.begin(), nodes.end(), [](const SettledNode& a, const SettledNode& b) { return a.lambda < b.lambda; });
  std::vector<Cluster> clusters;
  for (std::size_t i = 0; i < nodes.size();) {
    std::size_t j = i + 1;
    while (j < nodes.size() &&
           within_width(nodes[j - 1].lambda, nodes[j].lambda, width))
      ++j;
    Cluster c;
    double sum_lambda = 0;
    for (std::size_t k = i; k < j; ++k) {
      c.E += nodes[k].E;
      sum_lambda += nodes[k].E * nodes[k].lambda;
      c.residual = std::max(c.residual, nodes[k].residual);
    }
    c.members = static_cast<int>(j - i);
    c.lambda = c.E > 0 ? sum_lambda / c.E : nodes[i].lambda;
    double var = 0;
    for (std::size_t k = i; k < j; ++k) var += nodes[k].E * (nodes[k].lambda - c.lambda) * (nodes[k].lambda - c.lambda);
    c.spread = c.E > 0 ? std::sqrt(var / c.E) : 0.0;
    clusters.push_back(c);
    i = j;
  }
  return clusters;
}

LanczosRefinement::LanczosRefinement(const VelocitySpace& V, const PoincareForms& forms, const Eigen::VectorXd& w,
                                     double mass, const ClusterSettings& settings)
    : sil_(V, forms, w, mass), mass_(mass), settings_(settings) {
  settings_.sil.merge_width = settings.cluster_width;
}

Cluster LanczosRefinement::refine(const GaussNode& node) const {
  Cluster best;
  double half = settings_.slice_width * std::max(std::abs(node.lambda), 0.1);
  // Shift a little off the node: the node is not an eigenvalue, but a shift on one would make Q(σ) singular.
  const double sigma = std::clamp(node.lambda + 1e-3 * half, -1.999999, 1.999999);
  const double floor = settings_.floor * mass_;
  for (int attempt = 0; attempt <= settings_.widenings; ++attempt, half *= 4) {
    const double lo = std::max(node.lambda - half, -1.999999), hi = std::min(node.lambda + half, 1.999999);
    ShiftInvertRule rule = sil_.run(sigma, lo, hi, floor, settings_.sil);
    // A heavy node still moving is slow because others sit nearer the shift: run again shifted to it.
    if (const SettledNode* u = heaviest_unsettled(rule, 0.01 * node.E))
      rule = sil_.run(u->lambda + 1e-6 * std::max(std::abs(u->lambda), 0.1), lo, hi, floor, settings_.sil);
    // A node that matters and still did not settle is solver trouble: report it, never drop it.
    if (const SettledNode* u = heaviest_unsettled(rule, 0.01 * node.E))
      throw UnsettledNode(fmt::format(
          "eigensolver (shift-and-invert Lanczos) did not settle the node at lambda = {:.9g} (E = {:.3g}) in {} "
          "steps (last change of lambda {:.1e}, of E {:.1e}); raise --lanczos-steps",
          u->lambda, u->E, rule.steps, u->dlambda, u->dE));
    const auto clusters = merge_nodes(rule.settled, settings_.cluster_width);
    if (clusters.empty()) continue;
    best = *std::max_element(clusters.begin(), clusters.end(), [](const Cluster& a, const Cluster& b) { return a.E < b.E; });
    if (best.E >= 0.5 * node.E) break;  // the window holds the mode the node stands for
  }
  return best;
}

std::vector<Cluster> LanczosRefinement::search_gap(double a, double b, double floor) const {
  if (a > b) std::swap(a, b);
  const double sign = a > 0 ? 1.0 : -1.0;
  const double sigma = sign * std::sqrt(a * b);
  const double lo = a + 2 * settings_.cluster_width * std::max(std::abs(a), 0.1);
  const double hi = b - 2 * settings_.cluster_width * std::max(std::abs(b), 0.1);
  if (!(lo < hi)) return {};
  const ShiftInvertRule rule = sil_.run(sigma, lo, hi, floor, settings_.sil);
  std::vector<SettledNode> found = rule.settled;
  for (const SettledNode& u : rule.unsettled) {
    const ShiftInvertRule own =
        sil_.run(u.lambda + 1e-6 * std::max(std::abs(u.lambda), 0.1), lo, hi, floor, settings_.sil);
    for (const SettledNode& n : own.settled) {
      const bool known = std::any_of(found.begin(), found.end(), [&](const SettledNode& o) {
        return within_width(o.lambda, n.lambda, settings_.cluster_width);
      });
      if (!known) found.push_back(n);
    }
  }
  std::vector<Cluster> out;
  for (const Cluster& c : merge_nodes(found, settings_.cluster_width))
    if (c.E >= floor) out.push_back(c);
  return out;
}

std::vector<Cluster> refine_clusters_lanczos(const LanczosRefinement& refinement, const std::vector<GaussNode>& nodes,
                                             double cluster_width,
                                             const std::function<void(std::size_t, std::size_t)>& progress,
                                             const std::function<Cluster(const GaussNode&)>& fallback,
                                             int& fallbacks) {
  std::vector<Cluster> clusters;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    Cluster c;
    try {
      c = refinement.refine(nodes[i]);
    } catch (const UnsettledNode&) {
      c = fallback(nodes[i]);
      ++fallbacks;
    }
    if (progress) progress(i + 1, nodes.size());
    if (c.members == 0) continue;
    const bool duplicate = std::any_of(clusters.begin(), clusters.end(),
                                       [&](const Cluster& o) { return within_width(o.lambda, c.lambda, cluster_width); });
    if (!duplicate) clusters.push_back(c);
  }
  return clusters;
}

}  // namespace rc::modes
