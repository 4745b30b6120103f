// Lagrange nodes of the reference triangle, from gmsh itself so that the local order is by construction
// the one of the meshes gmsh writes (as in reference_element.cpp).
#include "lagrange_nodes.hpp"

#include "gmsh_lagrange_element.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rc::geometry {
namespace {

constexpr int kMaxOrder = 6;

// The nodes of an order-P triangle sit on the lattice (i/P, j/P), i + j <= P. Every lattice cell gives an
// "upper" sub-triangle (i, j), (i+1, j), (i, j+1) and, except on the diagonal, a "lower" one
// (i+1, j), (i+1, j+1), (i, j+1); both are counter-clockwise in (u, v), like the element itself.
std::vector<std::array<int, 3>> lattice_triangles(const std::vector<std::array<double, 2>>& points, int order) {
  std::map<std::pair<int, int>, int> at;
  for (std::size_t a = 0; a < points.size(); ++a) {
    const int i = static_cast<int>(std::lround(points[a][0] * order));
    const int j = static_cast<int>(std::lround(points[a][1] * order));
    if (std::abs(points[a][0] * order - i) > 1e-9 || std::abs(points[a][1] * order - j) > 1e-9 ||
        !at.emplace(std::pair{i, j}, static_cast<int>(a)).second)
      throw std::runtime_error("triangle_nodes: gmsh's order-" + std::to_string(order) +
                               " triangle nodes are not the equispaced lattice");
  }
  std::vector<std::array<int, 3>> tri;
  for (int i = 0; i < order; ++i)
    for (int j = 0; i + j < order; ++j) {
      tri.push_back({at.at({i, j}), at.at({i + 1, j}), at.at({i, j + 1})});
      if (i + j + 2 <= order) tri.push_back({at.at({i + 1, j}), at.at({i + 1, j + 1}), at.at({i, j + 1})});
    }
  return tri;
}

}  // namespace

TriangleNodes triangle_nodes(int order) {
  if (order < 1 || order > kMaxOrder)
    throw std::runtime_error("triangle_nodes: order " + std::to_string(order) + " is outside 1.." +
                             std::to_string(kMaxOrder));
  TriangleNodes t;
  t.order = order;
  t.nodes_per_element = (order + 1) * (order + 2) / 2;
  const detail::GmshLagrangeElement e =
      detail::gmsh_lagrange_element("triangle_nodes", "Triangle", 2, order, t.nodes_per_element);
  const std::size_t npe = t.nodes_per_element;
  for (std::size_t a = 0; a < npe; ++a) t.points.push_back({e.points[2 * a], e.points[2 * a + 1]});
  t.dN.resize(npe * npe * 2);
  for (std::size_t i = 0; i < npe * npe; ++i) {
    t.dN[2 * i] = e.grad[3 * i];
    t.dN[2 * i + 1] = e.grad[3 * i + 1];
  }
  t.sub_triangles = lattice_triangles(t.points, order);
  return t;
}

}  // namespace rc::geometry
