// Anisotropic wall layers in a 3-D cavity: thin elements across the wall, the size of the interior along it — what
// the viscous fluid's Ekman layers need (docs/volume.md §7), where isotropic elements would cost Ek^{-1} wall
// triangles. A core mesh lies inside the layers' thickness H; each of its wall triangles is extruded to the true wall
// (wall_layer_builder.hpp), in layers graded from `wall_size` at the wall, each prism split into three tetrahedra. High-
// order nodes follow the same map, so the layers' elements are curved with the wall and conform to the core's.
#pragma once

#include "volume_mesh.hpp"

namespace rc::geometry {

// The ellipsoid `shape` (kind "ellipsoid", any tilt) with wall layers: options.wall_layer the total thickness H,
// options.wall_size the first layer's, each next (1 + wall_growth) times thicker; options.size the core's elements.
// Throws std::runtime_error when H does not fit inside the smallest semi-axis.
// The ellipsoid's core is the ellipsoid shrunk by H, meshed by gmsh; its rays run along the core's exact normals and
// end on the exact ellipsoid.
VolumeMesh layered_ellipsoid(const VolumeShapeSpec& shape, const MeshOptions& options);

// A user's `volume` file (any shape; the same options): gmsh meshes the file at the layers' along-wall size
// (near_wall_size, else size) and order; each vertex of that mesh's curved wall is offset inwards so that every face
// round it moves by H along its normal (at an edge or corner of the wall, by more along the bisector), and gmsh fills
// the flat-faced core inside the offset wall (a discrete surface bounding a volume of its built-in kernel). Each core
// wall node's ray ends on the node of the first mesh's wall that it was offset from, so the layers end on the file's
// own curved surfaces. Throws std::runtime_error where the offset folds (layers thicker than the wall's radius of
// curvature or half a gap).
VolumeMesh layered_volume_file(const VolumeShapeSpec& shape, const MeshOptions& options);

}  // namespace rc::geometry
