#include "cavity_table.hpp"

#include "cluster_fields.hpp"
#include "cluster_selection.hpp"
#include "convergence.hpp"
#include "progress.hpp"
#include "discretisation.hpp"
#include "lanczos_refinement.hpp"
#include "partial_fill_table.hpp"
#include "separable_table.hpp"
#include "slice_refinement.hpp"
#include "table_assembly.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace rc::modes {

// Spheres and spheroids: their single coupling mode p ∝ r z is a polynomial that every order ≥ 2 represents
// exactly, so that only the wall's approximation errs: at order 6 a fifth of the smallest dimension gives λ, E,
// J_zh and A_f to ≤ 3e-10 (docs/modes.md, "Accuracy at default settings") in about 60 % of the time of an eighth.
geometry::MeshOptions mesh_method_defaults(const geometry::ShapeSpec& shape, geometry::MeshOptions mesh) {
  if (mesh.size == 0 && (shape.kind == "sphere" || shape.kind == "spheroid")) {
    geometry::check_shape(shape);
    const double d = shape.kind == "sphere" ? shape.dims.at("radius")
                                            : std::min(shape.dims.at("a"), shape.dims.at("c"));
    mesh.size = d / 5;
  }
  return mesh;
}

namespace {

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

// The survey's Gauss rule places few nodes where the modes crowd towards λ = 0, and can miss a heavy mode
// between two it found (measured: n = 0, j = 7..8 of the 2h/a = 2 cylinder, E ≈ 1e-2). Every gap between
// consecutive clusters that the selection keeps, of one sign and below gap_lambda in |λ|, is searched once
// (LanczosRefinement::search_gap) for clusters as heavy as the lightest one kept. Returns how many it added.
int fill_gaps(const LanczosRefinement& refinement, std::vector<Cluster>& clusters, const TableRequest& req,
              double sum_rule, Progress& progress) {
  if (clusters.empty()) return 0;
  auto kept = clusters;
  sort_by_energy(kept);
  kept.resize(std::max<std::size_t>(1, selected_count(kept, req.selection, sum_rule)));
  const double floor = 0.5 * kept.back().E;
  std::sort(kept.begin(), kept.end(), [](const Cluster& a, const Cluster& b) { return a.lambda < b.lambda; });
  int added = 0;
  for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
    const double a = kept[i].lambda, b = kept[i + 1].lambda;
    if (a * b <= 0 || std::max(std::abs(a), std::abs(b)) > req.clusters.gap_lambda) continue;
    if (std::min(std::abs(a), std::abs(b)) < req.selection.geostrophic_cutoff) continue;
    for (const Cluster& c : refinement.search_gap(a, b, floor)) {
      const bool known = std::any_of(clusters.begin(), clusters.end(), [&](const Cluster& o) {
        return within_width(o.lambda, c.lambda, req.clusters.cluster_width);
      });
      if (!known) { clusters.push_back(c); ++added; }
    }
    progress.step(fmt::format("gap {}/{}", i + 1, kept.size() - 1), i + 1, kept.size() - 1);
  }
  return added;
}

struct FoundClusters {
  std::vector<Cluster> clusters;
  std::string solver;
};

FoundClusters find_clusters(const Discretisation& d, const SpectralSurvey& survey, const TableRequest& req,
                            Progress& progress) {
  FoundClusters f;
  if (req.clusters.method == ClusterMethod::slices) {
    const auto nodes = candidate_nodes(survey, req.selection, d.sum_rule);
    f.clusters = refine_clusters(d.forms, nodes, req.clusters, [&](std::size_t done, std::size_t total) {
      progress.step(fmt::format("cluster {}/{}", done, total), done, total);
    }, &f.solver);
    return f;
  }
  const LanczosRefinement refinement(d.velocity, d.forms, d.coupling, d.sum_rule, req.clusters);
  const auto nodes = candidate_nodes(survey, req.selection, d.sum_rule);
  int fallbacks = 0;
  // Nodes in dense parts of the spectrum (cones) may not settle: SLEPc slices refine those.
  std::optional<QuadraticEigenSolver> slicer;
  const auto fallback = [&](const GaussNode& n) {
    if (!slicer) slicer.emplace(d.forms, req.clusters.qep);
    return refine_node(*slicer, n, req.clusters);
  };
  f.clusters = refine_clusters_lanczos(refinement, nodes, req.clusters.cluster_width, [&](std::size_t done, std::size_t total) {
    progress.step(fmt::format("cluster {}/{}", done, total), done, total);
  }, fallback, fallbacks);
  const int added = req.clusters.fill_gaps ? fill_gaps(refinement, f.clusters, req, d.sum_rule, progress) : 0;
  f.solver = fmt::format("survey (Lanczos Gauss rule of the coupling measure, {} steps) + shift-and-invert Lanczos "
                         "Gauss rules (MUMPS LDL^T of Q(sigma)) around each node", survey.steps);
  if (fallbacks > 0)
    f.solver += fmt::format("; {} node(s) that did not settle refined by SLEPc PEP stoar spectrum slicing", fallbacks);
  if (added > 0) f.solver += fmt::format("; {} cluster(s) found in gaps between clusters", added);
  return f;
}

}  // namespace

namespace {

// --target: the integrals of the ideal discretisation and the given frequencies as rows (TableRequest::targets).
ModeTable target_table(const TableRequest& req, Progress& progress_lines) {
  const Discretisation d(req.shape, mesh_method_defaults(req.shape, req.mesh));
  progress_lines.step(fmt::format("assembled {} dofs, J_zh = {:.10g}; targets given, no survey", d.space.ndof(),
                                  d.zhukovsky.J_zh));
  ModeTable t = start_table(req.shape, d.fluid, d.zhukovsky.J_zh);
  t.fe_order = d.space.order();
  t.mesh_h = d.space.mesh().size;
  t.ndof = d.space.ndof();
  t.solver = fmt::format("given targets (--target {}): no ideal survey", fmt::join(req.targets, ","));
  std::vector<Cluster> rows;
  for (const double lambda : req.targets) rows.push_back({lambda, 0.0, 0.0, 0.0, 1});
  add_modes(t, rows);
  t.wall_seconds = progress_lines.elapsed();
  return t;
}

}  // namespace

ModeTable compute_mode_table(const TableRequest& req, const ProgressFn& progress, ModeFields* fields) {
  validate(req.selection);
  if (req.check_convergence) validate_convergence_tolerance(req.convergence_tolerance);
  // Lines at least every 5 s while working, with the time left once clusters are counted (progress.hpp).
  Progress progress_lines(progress);
  auto report = [&](const std::string& what) { progress_lines.step(what); };
  if (!req.targets.empty()) return target_table(req, progress_lines);

  if (req.fill < 1) {
    const PartialFillTableSettings settings{req.shape, req.mesh, req.fill, req.selection, req.convergence_tolerance,
                                            req.check_convergence};
    if (req.method == TableMethod::separable && fields)
      throw std::runtime_error("--fields needs --method mesh (the separable solver keeps no 2-D mesh)");
    return req.method == TableMethod::separable ? partially_filled_cylinder_table(settings, report)
                                                : partially_filled_mesh_table(settings, report, fields);
  }
  if (req.method == TableMethod::separable) {
    if (fields) throw std::runtime_error("--fields needs --method mesh (the separable solver keeps no 2-D mesh)");
    return separable_cylinder_table({req.shape, req.mesh, req.selection, req.convergence_tolerance,
                                     req.check_convergence}, report);
  }
  const Discretisation d(req.shape, mesh_method_defaults(req.shape, req.mesh));
  const FESpace& space = d.space;
  const FluidIntegrals& fluid = d.fluid;
  const ZhukovskyResult& zh = d.zhukovsky;
  const double sum_rule = d.sum_rule;
  report(fmt::format("assembled {} dofs, J_zh = {:.10g}", space.ndof(), zh.J_zh));

  const SpectralSurvey survey = survey_spectral_measure(d.velocity, d.stiffness, d.coupling, req.survey);
  report(fmt::format("spectral survey: {} Lanczos steps", survey.steps));
  auto [found, solver] = find_clusters(d, survey, req, progress_lines);
  auto clusters = select_clusters(std::move(found), req.selection, sum_rule);
  ConvergenceCheck convergence;
  if (req.check_convergence) {
    report("convergence check on a coarser discretisation");
    geometry::MeshOptions used = req.mesh;
    used.size = space.mesh().size;
    convergence = check_convergence(req.shape, used, clusters, req.clusters, req.convergence_tolerance, space.ndof());
  }

  ModeTable t = start_table(req.shape, fluid, zh.J_zh);
  t.fe_order = space.order();
  t.mesh_h = space.mesh().size;
  t.mesh_h_radial = req.mesh.radial_size;
  t.ndof = space.ndof();
  t.solver = solver.empty() ? "no cluster needed refinement" : solver;
  t.tolerance = req.clusters.method == ClusterMethod::slices ? req.clusters.qep.tolerance
                                                              : req.clusters.sil.lambda_tolerance;
  if (req.check_convergence) add_convergence(t, convergence, req.convergence_tolerance);
  add_bands(t, band_weights(survey.nodes));
  add_modes(t, clusters);
  t.sort_by_energy();
  if (fields)
    *fields = cluster_fields(space, d.forms, t, {req.clusters.cluster_width, req.clusters.qep},
                             [&](std::size_t done, std::size_t total) {
                               progress_lines.step(fmt::format("fields {}/{}", done, total), done, total);
                             });
  t.wall_seconds = progress_lines.elapsed();
  return t;
}

}  // namespace rc::modes
