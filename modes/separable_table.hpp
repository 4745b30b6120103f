// A cylinder's mode table by the separable solver (separable_cylinder.hpp): the grid from the request, every
// eigenpair, the selection, per-mode convergence against a grid twice as coarse, exact discrete band weights.
// docs/modes.md, "Separable cylinder solver".
#pragma once

#include "cavity_table.hpp"
#include "separable_cylinder.hpp"

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

// compute_mode_table's separable branch (the request's selection and tolerance already validated there).
ModeTable separable_cylinder_table(const TableRequest& request, const ProgressFn& report);

}  // namespace rc::modes
