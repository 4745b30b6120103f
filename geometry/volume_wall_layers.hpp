// Anisotropic wall layers in a 3-D cavity (the ellipsoid): thin elements across the wall, the size of the interior
// along it — what the viscous fluid's Ekman layers need (docs/volume.md §7), where isotropic elements would cost
// Ek^{-1} wall triangles. gmsh meshes the core, the ellipsoid shrunk by the layers' thickness H; each of its boundary
// triangles is extruded to the true wall along the core's exact normals (each ray ends on the exact ellipsoid), in
// layers graded from `wall_size` at the wall, and each prism is split into three tetrahedra with the diagonals chosen by
// the vertices' numbers (so that neighbouring prisms agree). High-order nodes follow the same map, so the layers'
// elements are curved with the wall and conform to the core's.
#pragma once

#include "volume_mesh.hpp"

namespace rc::geometry {

// The ellipsoid `shape` (kind "ellipsoid", any tilt) with wall layers: options.wall_layer the total thickness H,
// options.wall_size the first layer's, each next (1 + wall_growth) times thicker; options.size the core's elements.
// Throws std::runtime_error when H does not fit inside the smallest semi-axis.
VolumeMesh layered_ellipsoid(const VolumeShapeSpec& shape, const MeshOptions& options);

}  // namespace rc::geometry
