// The Lagrange nodes of the reference triangle of one order, in gmsh's local node order (the order of
// MeridianMesh::triangles), with what output of nodal fields needs:
//   * the gradients of every basis function at every node (a field's gradient at the mesh nodes), and
//   * the split of the triangle into order² straight sub-triangles through all its nodes, for viewers
//     that draw only linear triangles (cavity-modes --fields, docs/modes.md "Fields").
#pragma once

#include <array>
#include <vector>

namespace rc::geometry {

struct TriangleNodes {
  int order = 0;
  int nodes_per_element = 0;
  std::vector<std::array<double, 2>> points;    // (u, v) of local node a on the reference triangle
  std::vector<double> dN;                       // dN[(b * nodes_per_element + a) * 2 + d]: d/du (d = 0) or
                                                // d/dv (d = 1) of basis a at node b
  std::vector<std::array<int, 3>> sub_triangles; // local nodes of each sub-triangle, counter-clockwise in (u, v)
};

// Throws std::runtime_error if the order is outside 1..6.
TriangleNodes triangle_nodes(int order);

}  // namespace rc::geometry
