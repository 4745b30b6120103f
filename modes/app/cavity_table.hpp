// The whole cavity-modes pipeline for one cavity: mesh -> forms -> Zhukovsky inertia -> spectral survey
// -> clusters -> mode table (docs/physics.md §2 and §4).
#pragma once

#include "cluster.hpp"
#include "cluster_selection.hpp"
#include "meridian_mesh.hpp"
#include "mode_table.hpp"
#include "spectral_survey.hpp"

#include <functional>
#include <optional>
#include <string>

namespace rc::modes {

// How a table is computed: `mesh` (every shape) meshes the meridian section with gmsh and finds clusters of the
// 2-D FE problem (survey + refinement, above); `separable` (cylinders only) separates the cylinder's problem
// exactly on a tensor-product grid and solves every radial problem densely (separable_cylinder.hpp).
enum class TableMethod { mesh, separable };

struct TableRequest {
  TableMethod method = TableMethod::mesh;
  geometry::ShapeSpec shape;
  geometry::MeshOptions mesh;
  ModeSelection selection;
  SurveySettings survey;
  ClusterSettings clusters;
  double convergence_tolerance = 1e-6;  // per-cluster flag against a coarser discretisation (convergence.hpp)
  bool check_convergence = true;
  // Given frequencies λ instead of the survey's clusters (cavity-modes --target, viscous tables only): the table
  // holds the frozen-fluid integrals and J_zh, and one row per target with E = 0 (no survey, no clusters): the
  // viscous continuation then takes the damped mode nearest each (viscous_table.hpp).
  std::vector<double> targets;
  // The liquid's volume fraction (cavity-modes --fill): below 1 a partially filled tank, its free surface the coaxial
  // cylinder of rapid spin (docs/physics.md §2, "Partially filled tanks"); so far the cylinder by the separable method.
  double fill = 1;
};

// The mesh method's element size where the request leaves it 0: geometry's default (1/8 of the smallest
// dimension, docs/geometry.md), except spheres and spheroids: 1/5 (cavity_table.cpp says why).
geometry::MeshOptions mesh_method_defaults(const geometry::ShapeSpec& shape, geometry::MeshOptions mesh);

using ProgressFn = std::function<void(const std::string&)>;

// Throws std::runtime_error with a one-line cause on bad input or solver failure. With `fields`, also the
// mesh and each kept mode's p and V at the nodes (cluster_fields.hpp; cavity-modes --fields).
ModeTable compute_mode_table(const TableRequest& request, const ProgressFn& progress = {},
                             ModeFields* fields = nullptr);

}  // namespace rc::modes
