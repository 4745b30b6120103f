// A partially filled tank's mode table (docs/physics.md §2, "Partially filled tanks"; docs/modes.md, "Partially
// filled tanks"): the separated cylinder's pairs (partial_fill_cylinder.hpp) or a
// mesh's (free_surface_mesh.hpp) as /modes rows with their offset
// coupling in /free_surface, a convergence flag per row against a grid twice as coarse.
#pragma once

#include "cluster_selection.hpp"
#include "meridian_mesh.hpp"
#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "partial_fill_spectrum.hpp"

#include <functional>
#include <string>

namespace rc::modes {

// The mesh method's default element size against geometry's default for the liquid's shape: the dense solver needs
// few dofs, and order 6 resolves the heavy modes on coarse meshes (docs/modes.md, "Partially filled tanks").
inline constexpr double kFreeSurfaceSizeFactor = 3.5;
// The dense solver's limit in a table (free_surface_mesh.hpp): beyond it two levels (free_surface_sparse.hpp). Every
// default mesh measured stays below it (the largest of nine: 1364 unknowns, the annulus section), so a default table keeps
// every pair and its sum rule; above it the dense solve's cube costs more than the levels (measured 2026-11-27, the
// fill 0.9 cylinder at 2365 dofs: 93 s dense; docs/benchmarks.md, "Partially filled tanks: dense and two-level solvers").
inline constexpr int kDenseFreeSurfaceUnknowns = 1500;

// What the table needs of a cavity-modes request (resolved by the driver, app/cavity_table.cpp).
struct PartialFillTableSettings {
  geometry::ShapeSpec shape;     // separable: a cylinder without an inner rod; mesh: any built-in shape
  geometry::MeshOptions grid;    // separable: separable_table.hpp's defaults over b < r < a; mesh: the gmsh mesh
  double fill = 1;               // 0 < fill < 1
  ModeSelection selection;       // already validated
  double convergence_tolerance = 1e-6;
  bool check_convergence = true;
  int max_unknowns = kDenseFreeSurfaceUnknowns;  // mesh: the dense solver's limit
};

// /free_surface's attributes of a spectrum's table (its per-row t is added with the rows).
ModeTable::FreeSurface free_surface_attributes(const PartialFillSpectrum& s, double fill);

// Rows are chosen by their largest E about a point within one cavity height of the liquid's centroid,
// 2 (|a| + H |t|)², against the sum rule there (docs/modes.md says why). Throws std::runtime_error (one line) for a
// fill outside (0, 1) or a shape that is not a plain cylinder.
ModeTable partially_filled_cylinder_table(const PartialFillTableSettings& settings,
                                          const std::function<void(const std::string&)>& report);

// The same by the mesh method (free_surface_mesh.hpp) for any built-in shape with its free surface
// (geometry/free_surface.hpp), the convergence check on the mesh with its sizes doubled. An element size of 0 takes
// 3.5 × geometry's default for the liquid's shape.
// With `fields`, also each row's p, V and energy density at the mesh nodes (free_surface_fields.hpp).
ModeTable partially_filled_mesh_table(const PartialFillTableSettings& settings,
                                      const std::function<void(const std::string&)>& report,
                                      ModeFields* fields = nullptr);

}  // namespace rc::modes
