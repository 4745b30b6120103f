// Lagrange nodes of the reference tetrahedron, from gmsh itself so that the local order is by construction the one
// of the meshes gmsh writes (as lagrange_nodes.cpp for the triangle).
#include "tetrahedron_nodes.hpp"

#include "gmsh_lagrange_element.hpp"
#include "lagrange_nodes.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rc::geometry {
namespace {

constexpr int kMaxOrder = 6;
using Lattice = std::array<int, 3>;

std::map<Lattice, int> lattice_of(const std::vector<std::array<double, 3>>& points, int order) {
  std::map<Lattice, int> at;
  for (std::size_t a = 0; a < points.size(); ++a) {
    Lattice l{};
    bool on_lattice = true;
    for (int d = 0; d < 3; ++d) {
      l[d] = static_cast<int>(std::lround(points[a][d] * order));
      on_lattice = on_lattice && std::abs(points[a][d] * order - l[d]) < 1e-9;
    }
    if (!on_lattice || !at.emplace(l, static_cast<int>(a)).second)
      throw std::runtime_error("tetrahedron_nodes: gmsh's order-" + std::to_string(order) +
                               " tetrahedron nodes are not the equispaced lattice");
  }
  return at;
}

double signed_volume(const std::vector<std::array<double, 3>>& x, const std::array<int, 4>& t) {
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) e[k][d] = x[t[k + 1]][d] - x[t[0]][d];
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
}

// The order-P lattice (i, j, k), i + j + k <= P, cut into P³ tetrahedra: at every lattice point n an "upward"
// tetrahedron n, n+e1, n+e2, n+e3 (sum <= P−1); an octahedron n+e1, n+e2, n+e3, n+e1+e2, n+e1+e3, n+e2+e3 (sum <= P−2),
// cut into four along its diagonal n+e1 — n+e2+e3; and a "downward" tetrahedron n+e1+e2, n+e1+e3, n+e2+e3, n+e1+e2+e3
// (sum <= P−3). Counts C(P+2,3) + 4 C(P+1,3) + C(P,3) = P³; each is turned to positive volume.
std::vector<std::array<int, 4>> lattice_tetrahedra(const std::vector<std::array<double, 3>>& points, int order) {
  const auto at = lattice_of(points, order);
  const auto node = [&](int i, int j, int k) { return at.at({i, j, k}); };
  std::vector<std::array<int, 4>> tets;
  for (int i = 0; i < order; ++i)
    for (int j = 0; i + j < order; ++j)
      for (int k = 0; i + j + k < order; ++k) {
        const int s = i + j + k;
        tets.push_back({node(i, j, k), node(i + 1, j, k), node(i, j + 1, k), node(i, j, k + 1)});
        if (s <= order - 2) {
          const int a = node(i + 1, j, k), b = node(i, j + 1, k + 1);  // the diagonal
          // The equator around it, each consecutive pair an edge of the octahedron.
          const int ring[4] = {node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k)};
          for (int q = 0; q < 4; ++q) tets.push_back({a, b, ring[q], ring[(q + 1) % 4]});
        }
        if (s <= order - 3)
          tets.push_back({node(i + 1, j + 1, k), node(i + 1, j, k + 1), node(i, j + 1, k + 1), node(i + 1, j + 1, k + 1)});
      }
  for (auto& t : tets)
    if (signed_volume(points, t) < 0) std::swap(t[2], t[3]);
  return tets;
}

}  // namespace

TetrahedronNodes tetrahedron_nodes(int order) {
  if (order < 1 || order > kMaxOrder)
    throw std::runtime_error("tetrahedron_nodes: order " + std::to_string(order) + " is outside 1.." +
                             std::to_string(kMaxOrder));
  TetrahedronNodes t;
  t.order = order;
  t.nodes_per_element = (order + 1) * (order + 2) * (order + 3) / 6;
  detail::GmshLagrangeElement e =
      detail::gmsh_lagrange_element("tetrahedron_nodes", "Tetrahedron", 3, order, t.nodes_per_element);
  for (int a = 0; a < t.nodes_per_element; ++a)
    t.points.push_back({e.points[3 * a], e.points[3 * a + 1], e.points[3 * a + 2]});
  t.dN = std::move(e.grad);
  t.sub_tetrahedra = lattice_tetrahedra(t.points, order);
  return t;
}

std::array<int, 4> tetrahedron_lattice(const std::array<double, 3>& uvw, int order) {
  const int i = static_cast<int>(std::lround(uvw[0] * order)), j = static_cast<int>(std::lround(uvw[1] * order)),
            k = static_cast<int>(std::lround(uvw[2] * order));
  return {order - i - j - k, i, j, k};
}

std::array<int, 3> face_vertices(int opposite) {
  std::array<int, 3> f{};
  for (int v = 0, i = 0; v < 4; ++v)
    if (v != opposite) f[i++] = v;
  return f;
}

std::vector<int> tetrahedron_face_nodes(int order, int opposite) {
  const auto tet = tetrahedron_nodes(order);
  std::map<std::array<int, 4>, int> by_lattice;
  for (int a = 0; a < tet.nodes_per_element; ++a) by_lattice[tetrahedron_lattice(tet.points[a], order)] = a;
  const std::array<int, 3> f = face_vertices(opposite);
  std::vector<int> out;
  for (const auto& [u, v] : triangle_nodes(order).points) {
    std::array<int, 4> l{};
    l[f[1]] = static_cast<int>(std::lround(u * order));
    l[f[2]] = static_cast<int>(std::lround(v * order));
    l[f[0]] = order - l[f[1]] - l[f[2]];
    out.push_back(by_lattice.at(l));
  }
  return out;
}

}  // namespace rc::geometry
