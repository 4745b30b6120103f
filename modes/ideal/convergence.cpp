#include "convergence.hpp"

#include "discretisation.hpp"
#include "lanczos_refinement.hpp"
#include "slice_refinement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace rc::modes {

geometry::MeshOptions coarser(const geometry::MeshOptions& mesh, std::string& description) {
  geometry::MeshOptions c = mesh;
  c.size = 2 * mesh.size;
  c.radial_size = 2 * mesh.radial_size;
  description = c.radial_size > 0 ? fmt::format("order {} with the mesh sizes doubled (h = {:g}, radial {:g})", c.order,
                                                c.size, c.radial_size)
                                   : fmt::format("order {} with the mesh size doubled (h = {:g})", c.order, c.size);
  return c;
}

ClusterChange cluster_change(const Cluster& c, const Cluster& r, double tolerance) {
  ClusterChange change;
  change.dlambda = r.members > 0 ? std::abs(r.lambda - c.lambda) / std::abs(c.lambda) : 1.0;
  change.dE = r.members > 0 ? std::abs(r.E - c.E) / c.E : 1.0;
  change.converged = change.dlambda <= tolerance && change.dE <= tolerance;
  return change;
}

ConvergenceCheck check_convergence(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh,
                                   const std::vector<Cluster>& clusters, const ClusterSettings& settings,
                                   double tolerance, long fine_ndof) {
  ConvergenceCheck check;
  const geometry::MeshOptions reference = coarser(mesh, check.reference);
  const Discretisation d(shape, reference);
  if (d.space.ndof() == fine_ndof) {
    // The mesh did not change (a .msh section keeps its own mesh): nothing is compared, nothing is certified.
    check.reference = "no coarser mesh: the section's mesh does not change with the mesh size (a .msh file); "
                      "compare with a table of a coarser .msh (cavity-modes compare)";
    for (std::size_t i = 0; i < clusters.size(); ++i) check.changes.push_back({1.0, 1.0, false});
    return check;
  }
  const LanczosRefinement lanczos(d.velocity, d.forms, d.coupling, d.sum_rule, settings);
  std::optional<QuadraticEigenSolver> slicer;
  if (settings.method == ClusterMethod::slices) slicer.emplace(d.forms, settings.qep);
  for (const Cluster& c : clusters) {
    const GaussNode node{c.lambda, c.E};
    Cluster r;
    try {
      r = slicer ? refine_node(*slicer, node, settings) : lanczos.refine(node);
    } catch (const UnsettledNode&) {
      // As in the table: a node the Lanczos process cannot settle is refined by a slice.
      if (!slicer) slicer.emplace(d.forms, settings.qep);
      r = refine_node(*slicer, node, settings);
    }
    check.changes.push_back(cluster_change(c, r, tolerance));
  }
  return check;
}

void validate_convergence_tolerance(double tolerance) {
  if (!(tolerance > 0 && tolerance <= kLoosestConvergenceTolerance))
    throw std::runtime_error(fmt::format(
        "--convergence-tolerance must be in (0, {:g}] (got {:g}): a single comparison with a coarser mesh cannot "
        "certify looser convergence (unconverged cone clusters agree by chance to 3e-4, docs/cones.md)",
        kLoosestConvergenceTolerance, tolerance));
}

std::vector<double> band_edges() {
  std::vector<double> edges;
  for (int i = 0; i <= 40; ++i) edges.push_back(-2.0 + 0.1 * i);
  return edges;
}

BandWeights band_weights(const std::vector<GaussNode>& nodes) {
  const auto edges = band_edges();
  BandWeights b;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    double E = 0, El = 0;
    for (const auto& n : nodes)
      if (n.lambda >= edges[i] && (n.lambda < edges[i + 1] || (i + 2 == edges.size() && n.lambda <= edges[i + 1]))) {
        E += n.E;
        El += n.E * n.lambda;
      }
    b.lo.push_back(edges[i]);
    b.hi.push_back(edges[i + 1]);
    b.E.push_back(E);
    b.lambda_mean.push_back(E > 0 ? El / E : 0.0);
  }
  return b;
}

}  // namespace rc::modes
