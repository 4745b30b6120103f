#include "cavity_table.hpp"

#include "convergence.hpp"
#include "fe_space.hpp"
#include "poincare_forms.hpp"
#include "stiffness_solver.hpp"
#include "zhukovsky.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rc::modes {
namespace {

using Clock = std::chrono::steady_clock;

void validate(const ModeSelection& s) {
  if (s.modes && *s.modes < 1) throw std::runtime_error(fmt::format("--modes must be at least 1 (got {})", *s.modes));
  if (s.coverage && !(*s.coverage > 0 && *s.coverage <= 1))
    throw std::runtime_error(fmt::format("--coverage must be in (0, 1] (got {})", *s.coverage));
}

// How many of the items, sorted by E descending, the selection keeps (cavity_table.hpp).
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

template <class Item>
void sort_by_energy(std::vector<Item>& items) {
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.E > b.E; });
}

// Survey nodes worth refining, heaviest first. A node's weight only approximates its cluster's E, and two
// nodes may refine to one cluster, so a few spare nodes are refined beyond what the selection asks for.
std::vector<GaussNode> candidate_nodes(const SpectralSurvey& survey, const ModeSelection& sel, double sum_rule) {
  std::vector<GaussNode> nodes;
  for (const auto& n : survey.nodes)
    if (std::abs(n.lambda) >= sel.geostrophic_cutoff && n.E > 1e-14 * sum_rule) nodes.push_back(n);
  sort_by_energy(nodes);
  const std::size_t spares = sel.modes ? std::max(5, *sel.modes / 2) : sel.coverage ? 5 : 0;
  const std::size_t cap = std::max(sel.max_clusters, sel.modes.value_or(0) + 10);
  nodes.resize(std::min({selected_count(nodes, sel, sum_rule) + spares, nodes.size(), cap}));
  return nodes;
}

std::vector<Cluster> select_clusters(std::vector<Cluster> clusters, const ModeSelection& sel, double sum_rule) {
  sort_by_energy(clusters);
  // A table always has its heaviest cluster, even if it falls below the default threshold.
  clusters.resize(std::max(selected_count(clusters, sel, sum_rule), std::min<std::size_t>(1, clusters.size())));
  return clusters;
}

}  // namespace

ModeTable compute_mode_table(const TableRequest& req, const ProgressFn& progress) {
  validate(req.selection);
  if (req.check_convergence) validate_convergence_tolerance(req.convergence_tolerance);
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  // Progress only on runs that take a while, and at most about once a second.
  double last_report = 0;
  auto report = [&](const std::string& what) {
    const double t = elapsed();
    if (!progress || t < 1.0 || t - last_report < 1.0) return;
    last_report = t;
    progress(fmt::format("[{:6.2f} s] {}", t, what));
  };

  const FESpace space(geometry::mesh_meridian(req.shape, req.mesh));
  const FluidIntegrals fluid = integrate_fluid(space);
  const PoincareForms forms = assemble_poincare_forms(space, fluid.centroid_z);
  const StiffnessSolver stiffness(forms.M);
  const ZhukovskyResult zh = zhukovsky_inertia(forms, stiffness);
  const double sum_rule = fluid.A_f - zh.J_zh;
  report(fmt::format("assembled {} dofs, J_zh = {:.10g}", space.ndof(), zh.J_zh));

  const SpectralSurvey survey = survey_spectral_measure(space, fluid.centroid_z, stiffness, req.survey);
  report(fmt::format("spectral survey: {} Lanczos steps", survey.steps));
  const auto nodes = candidate_nodes(survey, req.selection, sum_rule);
  std::string solver;
  auto clusters = refine_clusters(forms, nodes, req.clusters, [&](std::size_t done, std::size_t total) {
    report(fmt::format("cluster {}/{}", done, total));
  }, &solver);
  clusters = select_clusters(std::move(clusters), req.selection, sum_rule);
  ConvergenceCheck convergence;
  if (req.check_convergence) {
    report("convergence check on a coarser discretisation");
    geometry::MeshOptions used = req.mesh;
    used.size = space.mesh().size;
    convergence = check_convergence(req.shape, used, clusters, req.clusters, req.convergence_tolerance);
  }

  ModeTable t;
  t.shape = req.shape.kind;
  t.dimensions = req.shape.dims;
  t.fe_order = space.order();
  t.mesh_h = space.mesh().size;
  t.ndof = space.ndof();
  t.m = 1;
  t.volume = fluid.volume;
  t.centroid_z = fluid.centroid_z;
  t.A_f = fluid.A_f;
  t.C_f = fluid.C_f;
  t.J_zh = zh.J_zh;
  t.sum_rule = sum_rule;
  t.solver = solver.empty() ? "no cluster needed refinement" : solver;
  t.tolerance = req.clusters.qep.tolerance;
  t.normalisation = "rho = 1, omega0 = 1; each cluster's V is normalised to N2 = |V|^2 = 1, a = (e1 x r, V), "
                    "so E = 2 a^2 / N2 (SPEC section 2)";
  if (req.check_convergence) {
    t.convergence_reference = convergence.reference;
    t.convergence_tolerance = req.convergence_tolerance;
    for (const auto& ch : convergence.changes) {
      t.dlambda.push_back(ch.dlambda);
      t.dE.push_back(ch.dE);
      t.converged.push_back(ch.converged ? 1 : 0);
    }
  }
  const BandWeights bands = band_weights(survey.nodes);
  t.bands.lo = bands.lo;
  t.bands.hi = bands.hi;
  t.bands.E = bands.E;
  t.bands.lambda_mean = bands.lambda_mean;
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
  t.sort_by_energy();
  t.wall_seconds = elapsed();
  return t;
}

}  // namespace rc::modes
