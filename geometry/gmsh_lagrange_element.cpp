#include "gmsh_lagrange_element.hpp"

#include "gmsh_session.hpp"

#include <gmsh.h>

#include <stdexcept>

namespace rc::geometry::detail {

GmshLagrangeElement gmsh_lagrange_element(const std::string& context, const std::string& family, int dim, int order,
                                          int expected_nodes) {
  GmshLagrangeElement e;
  with_gmsh(context, [&](GmshSession&) {
    const int type = gmsh::model::mesh::getElementType(family, order);
    std::string name;
    int element_dim = 0, element_order = 0, num_primary = 0;
    std::vector<double> local;  // must be empty: gmsh 4.8 appends to it
    gmsh::model::mesh::getElementProperties(type, name, element_dim, element_order, e.nodes, local, num_primary);
    // gmsh gives `element_dim` coordinates per node; the basis wants three (u, v, w).
    std::vector<double> uvw;
    for (int a = 0; a < e.nodes; ++a)
      for (int c = 0; c < 3; ++c) uvw.push_back(c < element_dim ? local[element_dim * a + c] : 0.0);
    for (int a = 0; a < e.nodes; ++a)
      for (int c = 0; c < dim; ++c) e.points.push_back(uvw[3 * a + c]);
    int components = 0, orientations = 0;
    gmsh::model::mesh::getBasisFunctions(type, uvw, "GradLagrange", components, e.grad, orientations);
  });
  const std::size_t npe = static_cast<std::size_t>(expected_nodes);
  if (e.nodes != expected_nodes || e.grad.size() != npe * npe * 3)
    throw std::runtime_error(context + ": unexpected gmsh basis of order " + std::to_string(order));
  return e;
}

}  // namespace rc::geometry::detail
