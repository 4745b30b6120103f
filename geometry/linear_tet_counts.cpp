#include "linear_tet_counts.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace rc::geometry {
namespace {

// Nodes inside one edge, face and tetrahedron of an order-p Lagrange mesh (p >= 1: each is 0 where none fits).
std::size_t edge_nodes(int p) { return static_cast<std::size_t>(p - 1); }
std::size_t face_nodes(int p) { return static_cast<std::size_t>((p - 1) * (p - 2) / 2); }
std::size_t tet_nodes(int p) { return static_cast<std::size_t>((p - 1) * (p - 2) * (p - 3) / 6); }

}  // namespace

std::size_t LinearTetCounts::nodes(int order) const {
  return vertices + edges * edge_nodes(order) + faces * face_nodes(order) + tetrahedra * tet_nodes(order);
}

std::size_t LinearTetCounts::wall_nodes(int order) const {
  return wall_vertices + wall_edges * edge_nodes(order) + wall_faces * face_nodes(order);
}

LinearTetCounts count_linear_tets(const std::vector<std::array<std::size_t, 4>>& tets) {
  using Face = std::array<std::size_t, 3>;
  std::map<Face, int> faces;  // sorted vertex triple -> how many tetrahedra have it
  std::set<std::array<std::size_t, 2>> edges;
  std::set<std::size_t> vertices;
  for (auto t : tets) {
    std::sort(t.begin(), t.end());
    vertices.insert(t.begin(), t.end());
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert({t[i], t[j]});
    for (int skip = 0; skip < 4; ++skip) {
      Face f{};
      for (int i = 0, k = 0; i < 4; ++i)
        if (i != skip) f[k++] = t[i];
      ++faces[f];
    }
  }
  LinearTetCounts c;
  c.vertices = vertices.size();
  c.edges = edges.size();
  c.faces = faces.size();
  c.tetrahedra = tets.size();
  std::set<std::array<std::size_t, 2>> wall_edges;
  std::set<std::size_t> wall_vertices;
  for (const auto& [f, n] : faces) {
    if (n != 1) continue;
    ++c.wall_faces;
    wall_vertices.insert(f.begin(), f.end());
    wall_edges.insert({f[0], f[1]});
    wall_edges.insert({f[0], f[2]});
    wall_edges.insert({f[1], f[2]});
  }
  c.wall_vertices = wall_vertices.size();
  c.wall_edges = wall_edges.size();
  return c;
}

}  // namespace rc::geometry
