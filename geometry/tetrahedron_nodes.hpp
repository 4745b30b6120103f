// The Lagrange nodes of the reference tetrahedron of one order, in gmsh's local node order (the order of
// VolumeMesh::tetrahedra), with what output of nodal fields on a 3-D cavity needs (the 3-D form of
// lagrange_nodes.hpp):
//   * the gradients of every basis function at every node (a field's gradient at the mesh nodes), and
//   * the split of the tetrahedron into order³ straight sub-tetrahedra through all its nodes, for viewers that draw
//     only linear cells (cavity-modes ellipsoid/volume --fields, docs/volume.md §5).
#pragma once

#include <array>
#include <vector>

namespace rc::geometry {

struct TetrahedronNodes {
  int order = 0;
  int nodes_per_element = 0;
  std::vector<std::array<double, 3>> points;         // (u, v, w) of local node a on the reference tetrahedron
  std::vector<double> dN;                            // dN[(b * nodes_per_element + a) * 3 + d]: d/du, d/dv, d/dw
                                                     // (d = 0, 1, 2) of basis a at node b
  std::vector<std::array<int, 4>> sub_tetrahedra;    // local nodes of each sub-tetrahedron, positive volume in (u, v, w)
};

// Throws std::runtime_error if the order is outside 1..6 or gmsh's nodes are not the equispaced lattice.
TetrahedronNodes tetrahedron_nodes(int order);

// The barycentric lattice weights of a reference node (u, v, w) of that order on vertices 0..3 (vertex 0 at the
// origin, 1, 2, 3 on the u, v, w axes), summing to the order: a node shared by neighbouring elements has the same
// weights on the same global vertices whatever their local orientations.
std::array<int, 4> tetrahedron_lattice(const std::array<double, 3>& uvw, int order);

// The tetrahedron's local node at each node of the triangle on its face opposite vertex `opposite`, the face's
// vertices (face_vertices) taken in ascending local order: triangle node (u, v) has barycentric weights 1 − u − v, u, v
// on them, in lagrange_nodes.hpp's triangle order.
std::vector<int> tetrahedron_face_nodes(int order, int opposite);
std::array<int, 3> face_vertices(int opposite);

}  // namespace rc::geometry
