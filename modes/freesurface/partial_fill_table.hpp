// A partially filled cylinder's mode table (docs/physics.md §2, "Partially filled tanks"; docs/modes.md, "Partially
// filled tanks"): the separated problem's pairs (partial_fill_cylinder.hpp) as /modes rows with their offset
// coupling in /free_surface, a convergence flag per row against a grid twice as coarse.
#pragma once

#include "cluster_selection.hpp"
#include "meridian_mesh.hpp"
#include "mode_table.hpp"

#include <functional>
#include <string>

namespace rc::modes {

// What the table needs of a cavity-modes request (resolved by the driver, app/cavity_table.cpp).
struct PartialFillTableSettings {
  geometry::ShapeSpec shape;     // a cylinder without an inner rod
  geometry::MeshOptions grid;    // as for the separable method (separable_table.hpp's defaults, over b < r < a)
  double fill = 1;               // 0 < fill < 1
  ModeSelection selection;       // already validated
  double convergence_tolerance = 1e-6;
  bool check_convergence = true;
};

// Rows are chosen by their largest E about a point within one cavity height of the liquid's centroid,
// 2 (|a| + H |t|)², against the sum rule there (docs/modes.md says why). Throws std::runtime_error (one line) for a
// fill outside (0, 1) or a shape that is not a plain cylinder.
ModeTable partially_filled_cylinder_table(const PartialFillTableSettings& settings,
                                          const std::function<void(const std::string&)>& report);

}  // namespace rc::modes
