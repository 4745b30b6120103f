// Internal to rc_geometry: the prismatic wall layers of a 3-D cavity, built outwards from a core mesh's wall to the
// true wall (docs/volume.md §7, "Wall layers"). The shape decides where each core wall node's ray ends (the ellipsoid:
// along the core's exact normal onto the exact ellipsoid; a user's file: on the node of the first mesh's curved wall
// that the core node was offset from); the layers, their grading, the split of each prism into three tetrahedra and
// the high-order nodes are the same for every shape.
#pragma once

#include "volume_mesh.hpp"

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rc::geometry::detail {

using Point = std::array<double, 3>;
// A point of the core's wall lattice: its barycentric lattice weights on the core's global vertices, sorted.
using SurfaceKey = std::vector<std::pair<int, int>>;

struct WallRay {
  Point start{}, direction{};  // a core wall node and the unit direction towards the true wall
  double length = 0;           // to the true wall along it
};

// "(x, y, z)" to four digits: where an error message points.
std::string place(const Point& p);

// The ray from a core wall node to the point of the true wall it maps to.
WallRay ray_between(const Point& start, const Point& end);

// Distances from the wall of the layers' boundaries: 0, wall_size, wall_size (2 + g), ... up to wall_layer.
std::vector<double> layer_depths(const MeshOptions& options);

// The core's wall: each face that one tetrahedron alone has, with its three vertices and, for every core node on it,
// the node's lattice key.
struct CoreWall {
  std::vector<std::array<int, 3>> faces;  // core vertex indices
  std::map<SurfaceKey, int> node_of;      // lattice key -> core node
};
CoreWall core_wall(const VolumeMesh& core);

// Where the ray of the core wall node with this key (at this position) ends.
using RayOf = std::function<WallRay(const SurfaceKey& key, const Point& core_node)>;

// Appends to `core` the layers between its wall and the true wall (depths from layer_depths, every ray's length
// split in the same proportions), with their nodes. Throws std::runtime_error naming the place where a prism folds
// (its three tetrahedra not all of the orientation its rays give: layers thicker than the wall's bends allow).
void add_wall_layers(VolumeMesh& core, const CoreWall& wall, const std::vector<double>& depths, const RayOf& ray);

}  // namespace rc::geometry::detail
