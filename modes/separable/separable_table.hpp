// A cylinder's mode table by the separable solver (separable_cylinder.hpp): the grid from the request, every
// eigenpair, the selection, per-mode convergence against a grid twice as coarse, exact discrete band weights.
// docs/modes.md, "Separable cylinder solver".
#pragma once

#include "cluster_selection.hpp"
#include "meridian_mesh.hpp"
#include "mode_table.hpp"
#include "separable_cylinder.hpp"

#include <functional>
#include <string>

namespace rc::modes {

// Defaults where the request leaves 0, with d = min(radius, height): order 10, axial element size 3d/8,
// radial element size max(d, radius/2)/8, two corner layers. The axial count is rounded up to an even number, so that
// coarser() keeps the grid symmetric about the mid-plane. Throws std::runtime_error (one line) for a shape that
// is not a valid cylinder or an order outside 1..12.
SeparableGrid separable_grid(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh);

// The reference of the convergence flags: the same order with every two neighbouring elements merged, in r and
// in z (merged_pairs, line_space.hpp), so that every element at least doubles — also near the lids, where
// halving the uniform count alone would leave the corner layers' sizes as they were.
SeparableGrid coarser(const SeparableGrid& grid);

// What the separable table needs of a cavity-modes request (resolved by the driver, app/cavity_table.cpp).
struct SeparableTableSettings {
  geometry::ShapeSpec shape;         // a cylinder
  geometry::MeshOptions grid;        // order, axial size (size), radial size; 0 = the defaults above
  ModeSelection selection;           // already validated
  double convergence_tolerance = 1e-6;
  bool check_convergence = true;
};

// compute_mode_table's separable branch.
ModeTable separable_cylinder_table(const SeparableTableSettings& settings,
                                   const std::function<void(const std::string&)>& report);

}  // namespace rc::modes
