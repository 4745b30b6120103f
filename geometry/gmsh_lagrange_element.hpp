// Internal to rc_geometry: gmsh's own Lagrange element of a family and order — its nodes on the reference element and
// the gradients of its basis there — so that the local node order of our reference elements (lagrange_nodes.hpp,
// tetrahedron_nodes.hpp) is by construction the one of the meshes gmsh writes.
#pragma once

#include <string>
#include <vector>

namespace rc::geometry::detail {

struct GmshLagrangeElement {
  std::vector<double> points;  // per node, its `dim` reference coordinates
  std::vector<double> grad;    // per node, per basis function, ∂N/∂(u, v, w): npe · npe · 3
  int nodes = 0;
};

// `family`: "Triangle" (dim 2) or "Tetrahedron" (dim 3). Throws std::runtime_error("<context>: …") where gmsh fails
// or gives a basis of another size than (order + 1)(order + 2)/2 or (order + 1)(order + 2)(order + 3)/6 nodes.
GmshLagrangeElement gmsh_lagrange_element(const std::string& context, const std::string& family, int dim, int order,
                                          int expected_nodes);

}  // namespace rc::geometry::detail
