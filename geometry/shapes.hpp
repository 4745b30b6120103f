// Internal to rc_geometry: the built-in shapes as gmsh CAD models.
#pragma once

#include "meridian_mesh.hpp"

namespace rc::geometry::detail {

// Checks the kind and dimensions of a shape (file existence for sections is checked when opened).
// Throws std::runtime_error naming the offending kind, dimension or value.
void validate_shape(const ShapeSpec& shape);

// Smallest characteristic length of a built-in shape (sphere: radius; spheroid: min(a, c);
// cylinder, cone: min(radius, height)); the default mesh size is a fraction of it.
double smallest_dimension(const ShapeSpec& shape);

// Builds the meridian half-section of a built-in shape in the current gmsh model with the physical
// groups "fluid", "wall" and "axis", every point carrying `size` as its mesh size. radial_size > 0
// (cylinder only) makes the mesh structured: ⌈radius / radial_size⌉ × ⌈height / size⌉ rectangles, each
// cut into two triangles.
// With `layers` (wall_size > 0 and wall_layer > 0), a shape that builds its wall layers into the CAD model (the
// cone: structured strips along the slant and the lid, see build_layered_cone in shapes.cpp) does so and
// returns true; the others return false and the caller grades the mesh with gmsh fields instead.
bool build_shape(const ShapeSpec& shape, double size, double radial_size = 0, const MeshOptions* layers = nullptr);

}  // namespace rc::geometry::detail
