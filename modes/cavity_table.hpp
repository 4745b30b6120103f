// The whole cavity-modes pipeline for one cavity: mesh -> forms -> Zhukovsky inertia -> spectral survey
// -> clusters -> mode table (SPEC §2 and §4).
#pragma once

#include "cluster.hpp"
#include "meridian_mesh.hpp"
#include "mode_table.hpp"
#include "spectral_survey.hpp"

#include <functional>
#include <optional>
#include <string>

namespace rc::modes {

// Which clusters a table keeps (docs/modes.md):
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

struct TableRequest {
  geometry::ShapeSpec shape;
  geometry::MeshOptions mesh;
  ModeSelection selection;
  SurveySettings survey;
  ClusterSettings clusters;
  double convergence_tolerance = 1e-6;  // per-cluster flag against a coarser discretisation (convergence.hpp)
  bool check_convergence = true;
};

using ProgressFn = std::function<void(const std::string&)>;

// Throws std::runtime_error with a one-line cause on bad input or solver failure. With `fields`, also the
// mesh and each kept mode's p and V at the nodes (cluster_fields.hpp; cavity-modes --fields).
ModeTable compute_mode_table(const TableRequest& request, const ProgressFn& progress = {},
                             ModeFields* fields = nullptr);

}  // namespace rc::modes
