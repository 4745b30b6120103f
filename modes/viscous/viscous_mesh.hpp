// The viscous meridian mesh: the wall's anisotropic layers where gmsh can make them, else isotropic grading.
#pragma once

#include "meridian_mesh.hpp"

#include <string>

namespace rc::modes {

// Anisotropic wall layers where they fit, else isotropic grading. gmsh's layers can invert an element where a wall
// meets the axis at one interior size and not at a slightly smaller one (Kore's shell at Ek = 1e-4: at 0.125 and 0.1,
// not at 0.08; docs/benchmarks.md, "Kore"), and the grading costs several times the unknowns (645 000 against 105 500
// there), so up to six smaller interior sizes (× 0.8 each) are tried first (the same shell at Ek = 1e-5 holds its
// layers from 0.064 down; the grading there took 2.2 million unknowns, 105 s and 22 GB). What was used is `mesh` afterwards,
// recorded in the table (its size, and wall_layer = 0 for the grading).
// gmsh's failures to mesh the layers at all (an edge of the layered wall it cannot recover, measured on the sphere
// filled to 0.6 at Ek = 1e-3 with interior sizes 0.1 to 0.14) are taken the same way. Throws std::runtime_error when
// even the grading fails.
geometry::MeridianMesh viscous_mesh(const geometry::ShapeSpec& shape, geometry::MeshOptions& mesh);

// "order 6, h = 0.058, wall 0.00095, near-wall 0.01": a viscous mesh in one phrase.
std::string mesh_text(const geometry::MeshOptions& mesh);

}  // namespace rc::modes
