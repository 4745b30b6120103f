// The gmsh size fields the meshers share (meridian_mesh.cpp, volume_mesh.cpp): elements of `size_min` within
// `dist_min` of some entities, growing linearly to `size_max` at `dist_max` (a Threshold on a Distance field).
#pragma once

#include <vector>

namespace rc::geometry {

struct DistanceTo {
  std::vector<double> points, curves, surfaces;  // gmsh tags
  double points_per_curve = 0;                   // the curves' sampling (0: gmsh's default)
};

// Returns the Threshold field's tag.
int distance_threshold(const DistanceTo& to, double size_min, double size_max, double dist_min, double dist_max);

}  // namespace rc::geometry
