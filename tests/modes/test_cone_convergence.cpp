// Cones (docs/cones.md): inertial waves focus towards a cone's apex and the positive-λ part of its
// spectrum does not resolve into converging modes, so at the default discretisation a cone table must show
// unconverged clusters, and must never present an unconverged cluster as converged.
#include "cavity_table.hpp"
#include "convergence.hpp"
#include "discretisation.hpp"
#include "lanczos_refinement.hpp"
#include "slice_refinement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace rc::modes;

namespace {

// The cone of the study with apex half-angle 45° (radius = height = 1), at the program's defaults: order 6,
// h = 1/8 of the smallest dimension. Only the 8 heaviest clusters are asked for, to keep the test short;
// flags are per cluster, so these are the flags the default table gives its 8 heaviest clusters.
TableRequest default_cone_request() {
  TableRequest r;
  r.shape.kind = "cone";
  r.shape.dims = {{"radius", 1.0}, {"height", 1.0}};
  r.mesh.order = 6;
  r.selection.modes = 8;
  return r;
}

// max(relative change of λ, of E) of each node's cluster recomputed (the table's lanczos rule) on the mesh of
// size h/2, twice as FINE as the table's; a node that does not settle there is refined by a SLEPc slice,
// as the table does.
std::vector<double> changes_on_finer_mesh(const TableRequest& req, double h, const std::vector<GaussNode>& nodes) {
  rc::geometry::MeshOptions finer = req.mesh;
  finer.size = h / 2;
  const Discretisation d(req.shape, finer);
  const LanczosRefinement refinement(d.velocity, d.forms, d.coupling, d.sum_rule, req.clusters);
  const QuadraticEigenSolver slicer(d.forms, req.clusters.qep);
  std::vector<double> out;
  for (const auto& n : nodes) {
    Cluster c;
    try {
      c = refinement.refine(n);
    } catch (const UnsettledNode&) {
      c = refine_node(slicer, n, req.clusters);
    }
    out.push_back(c.members > 0 ? std::max(std::abs(c.lambda - n.lambda) / std::abs(n.lambda), std::abs(c.E - n.E) / n.E)
                                : 1.0);
  }
  return out;
}

}  // namespace

// One table, four checks: the flags follow their rule; at least one positive-λ cluster is not flagged, and the
// finer mesh confirms that it moves; no cluster is within reach of any accepted tolerance; every flagged cluster
// (the study flagged none, docs/cones.md) agrees with the mesh twice as fine.
TEST(ConeConvergence, DefaultDiscretisationFlagsAreHonest) {
  const auto req = default_cone_request();
  const auto t = compute_mode_table(req);
  ASSERT_EQ(t.converged.size(), t.size());
  ASSERT_GE(t.size(), 5u);
  std::printf("cone R=H=1, order %d, h = %g, %ld dofs (%.1f s), against %s:\n", t.fe_order, t.mesh_h, t.ndof,
              t.wall_seconds, t.convergence_reference.c_str());
  // Recomputed on the finer mesh: every flagged cluster and the heaviest unflagged positive-λ one.
  std::vector<std::size_t> probed;
  int unflagged_positive = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const bool probe_unflagged = !t.converged[i] && t.lambda[i] > 0 && unflagged_positive++ < 1;
    if (t.converged[i] || probe_unflagged) probed.push_back(i);
  }
  std::vector<GaussNode> nodes;
  for (std::size_t i : probed) nodes.push_back(GaussNode{t.lambda[i], t.E[i]});
  const auto finer = changes_on_finer_mesh(req, t.mesh_h, nodes);

  int positive_unconverged = 0, confirmed_moving = 0;
  double smallest_change = 1;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto at = std::find(probed.begin(), probed.end(), i);
    const double fine = at == probed.end() ? -1.0 : finer[static_cast<std::size_t>(at - probed.begin())];
    std::printf("  #%zu lambda %+.6f E %.4e  coarser mesh: dlambda %.1e dE %.1e  converged %d  finer mesh: %.1e\n",
                i + 1, t.lambda[i], t.E[i], t.dlambda[i], t.dE[i], t.converged[i], fine);
    EXPECT_EQ(t.converged[i], t.dlambda[i] <= t.convergence_tolerance && t.dE[i] <= t.convergence_tolerance);
    smallest_change = std::min(smallest_change, std::max(t.dlambda[i], t.dE[i]));
    if (t.converged[i]) {
      EXPECT_LE(fine, t.convergence_tolerance) << "cluster " << i + 1 << " flagged converged";
    }
    if (t.lambda[i] > 0 && !t.converged[i]) {
      ++positive_unconverged;
      if (fine > t.convergence_tolerance) ++confirmed_moving;
    }
  }
  std::printf("%d positive-lambda clusters not converged, %d of them checked and moving on the finer mesh; smallest "
              "change against the coarser mesh %.1e (loosest accepted tolerance %.0e)\n",
              positive_unconverged, confirmed_moving, smallest_change, kLoosestConvergenceTolerance);
  EXPECT_GE(positive_unconverged, 1);
  EXPECT_GE(confirmed_moving, 1);
  EXPECT_GT(smallest_change, kLoosestConvergenceTolerance) << "a cone cluster could be flagged at an accepted tolerance";
}

// Looser tolerances would let chance agreements of unconverged clusters pass as converged (docs/cones.md);
// the request is refused before any work is done.
TEST(ConeConvergence, RefusesALooseConvergenceTolerance) {
  auto req = default_cone_request();
  for (const double bad : {1e-2, 2 * kLoosestConvergenceTolerance, 0.0, -1e-6}) {
    req.convergence_tolerance = bad;
    EXPECT_THROW(compute_mode_table(req), std::runtime_error) << bad;
  }
}
