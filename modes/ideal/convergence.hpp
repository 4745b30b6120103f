// How far a table can be trusted: every cluster is recomputed on a coarser discretisation and
// its relative change of λ and E reported, with a converged flag; and the spectral weight in λ-bands
// covering (−2, 2) is reported from the survey's Gauss rule. See docs/modes.md, "Convergence".
#pragma once

#include "cluster.hpp"
#include "meridian_mesh.hpp"
#include "spectral_survey.hpp"

#include <string>
#include <vector>

namespace rc::modes {

struct ClusterChange {
  double dlambda = 0, dE = 0;  // relative changes against the coarser discretisation
  bool converged = false;
};

struct ConvergenceCheck {
  std::string reference;            // e.g. "order 5 on the same mesh"
  std::vector<ClusterChange> changes;  // one per cluster, in the order given
};

// A table's cluster against the same cluster recomputed on a coarser discretisation (members = 0: not found
// there, both changes 1).
ClusterChange cluster_change(const Cluster& table, const Cluster& reference, double tolerance);

// The coarser discretisation: the same order with the mesh size doubled. (One order lower on the same
// mesh was tried first and is not conservative: where corner singularities limit the convergence rate, P5
// and P6 on one mesh can err alike, and a 2h/a = 1 cylinder cluster was flagged converged at 1e-6 while
// 1.6e-6 from Stewartson's value.) `mesh.size` must be the size actually used (MeridianMesh::size).
geometry::MeshOptions coarser(const geometry::MeshOptions& mesh, std::string& description);

// The loosest --convergence-tolerance accepted. One comparison with a coarser mesh certifies a cluster only
// when the discretisation is in its asymptotic range. On cones (docs/cones.md) unconverged clusters change
// between meshes by a random-looking amount: among 578 measured cone clusters the smallest change was 3.3e-4,
// and the count below t falls about 7-fold per decade of t (1 below 1e-3, 8 below 1e-2, 57 below 0.1); all 7
// that a 1e-2 tolerance would flag and that could be judged were off the finest mesh by 1.3e-2..1.7. At 1e-5
// such a chance agreement is improbable (extrapolated: ~1e-5 per cluster); looser tolerances would flag
// unconverged clusters.
inline constexpr double kLoosestConvergenceTolerance = 1e-5;

// Throws std::runtime_error (one line, saying why) unless 0 < tolerance <= kLoosestConvergenceTolerance.
void validate_convergence_tolerance(double tolerance);

// Recomputes each cluster on `mesh` (as a node at its λ with its E, refined by the table's method) and compares.
// fine_ndof: the table's own size; a coarser mesh of the same size (a .msh section) certifies nothing, and no
// cluster is then flagged converged.
ConvergenceCheck check_convergence(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh,
                                   const std::vector<Cluster>& clusters, const ClusterSettings& settings,
                                   double tolerance, long fine_ndof);

// Band edges used by every table: width 0.1 over (−2, 2) (40 bands).
std::vector<double> band_edges();

struct BandWeights {
  std::vector<double> lo, hi, E, lambda_mean;
};
// Σ E and the E-weighted mean λ of the Gauss rule's nodes in each band.
BandWeights band_weights(const std::vector<GaussNode>& nodes);

}  // namespace rc::modes
