// The simplex counts of a linear tetrahedral mesh, from which the node count of the same mesh at any Lagrange order
// follows: a P_p tetrahedral mesh has one node per vertex, p − 1 per edge, (p − 1)(p − 2)/2 per face and
// (p − 1)(p − 2)(p − 3)/6 inside each tetrahedron. mesh_volume reports them before gmsh places the high-order nodes
// (at P6 most of a large mesh's meshing time: 30 s for a sphere at h 0.15), so a caller can refuse a mesh that
// cannot fit at once.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace rc::geometry {

struct LinearTetCounts {
  std::size_t vertices = 0, edges = 0, faces = 0, tetrahedra = 0;
  // On the boundary: the faces one tetrahedron alone has, with their edges and vertices.
  std::size_t wall_vertices = 0, wall_edges = 0, wall_faces = 0;

  std::size_t nodes(int order) const;       // every node of the order-p mesh
  std::size_t wall_nodes(int order) const;  // its nodes on the boundary faces
};

// Counts of the mesh whose tetrahedra have these four vertex ids each (any integer ids).
LinearTetCounts count_linear_tets(const std::vector<std::array<std::size_t, 4>>& tets);

// Called by mesh_volume on the linear mesh, before the high-order nodes; throws to refuse the mesh.
using LinearMeshCheck = std::function<void(const LinearTetCounts&)>;

}  // namespace rc::geometry
