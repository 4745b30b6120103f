#include "taylor_hood_space.hpp"

#include "lagrange_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace rc::modes {
namespace {

// A pressure node is identified across elements by its barycentric coordinates on the element's vertices,
// written with global vertex numbers and sorted: the nodes an edge shares with its neighbour then get the
// same key whatever the two elements' local orientations.
using NodeKey = std::vector<std::pair<int, int>>;  // (global vertex, lattice weight), weight > 0, sorted

NodeKey node_key(const int* vertices, std::array<double, 2> uv, int order) {
  const int i = static_cast<int>(std::lround(uv[0] * order)), j = static_cast<int>(std::lround(uv[1] * order));
  const std::array<int, 3> weight = {order - i - j, i, j};  // vertex 0 at (0,0), 1 at (1,0), 2 at (0,1)
  NodeKey key;
  for (int v = 0; v < 3; ++v)
    if (weight[v] > 0) key.emplace_back(vertices[v], weight[v]);
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

TaylorHoodSpace::TaylorHoodSpace(geometry::MeridianMesh mesh, int quadrature_degree)
    : geometry_(std::move(mesh), quadrature_degree) {
  const auto& m = geometry_.mesh();
  if (m.order < 2)
    throw std::runtime_error("the viscous solver needs elements of order >= 2 (Taylor-Hood P_k/P_(k-1)); got " +
                             std::to_string(m.order));
  const int npe = m.nodes_per_element;
  const std::size_t ne = m.num_triangles();

  // Velocity: one unknown per node and free component.
  std::vector<char> on_wall(m.nodes.size(), 0), on_axis(m.nodes.size(), 0);
  for (int n : m.wall_edges) on_wall[n] = 1;
  for (int n : m.axis_nodes) on_axis[n] = 1;
  for (int c : {kPlus, kMinus, kAxial}) {
    std::vector<int> node_dof(m.nodes.size(), -1);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      const bool fixed = on_wall[n] || (on_axis[n] && c != kMinus);
      if (!fixed) node_dof[n] = velocity_dofs_++;
    }
    velocity_[c].resize(ne * npe);
    for (std::size_t i = 0; i < ne * npe; ++i) velocity_[c][i] = node_dof[m.triangles[i]];
  }

  for (std::size_t e = 0; e < ne; ++e) {
    const int* v = m.triangles.data() + e * npe;
    const auto boundary = [&](int n) { return on_wall[n] || on_axis[n]; };
    if (boundary(v[0]) && boundary(v[1]) && boundary(v[2])) ++boundary_locked_;
  }

  // Pressure: order k − 1 nodes, shared by key, none on the axis.
  const int pk = m.order - 1;
  const auto nodes = geometry::triangle_nodes(pk);
  pressure_npe_ = nodes.nodes_per_element;
  std::map<NodeKey, int> numbered;
  pressure_.resize(ne * pressure_npe_);
  for (std::size_t e = 0; e < ne; ++e) {
    const int* vertices = m.triangles.data() + e * npe;
    for (int b = 0; b < pressure_npe_; ++b) {
      const NodeKey key = node_key(vertices, nodes.points[b], pk);
      const bool axis = std::all_of(key.begin(), key.end(), [&](const auto& kv) { return on_axis[kv.first] != 0; });
      int dof = -1;
      if (!axis) {
        auto [it, is_new] = numbered.try_emplace(key, velocity_dofs_ + pressure_dofs_);
        if (is_new) ++pressure_dofs_;
        dof = it->second;
      }
      pressure_[e * pressure_npe_ + b] = dof;
    }
  }
  if (velocity_dofs_ == 0 || pressure_dofs_ == 0)
    throw std::runtime_error("the mesh has no free velocity or pressure unknown (too coarse for order " +
                             std::to_string(m.order) + ")");

  // Pressure basis at the velocity quadrature points (same rule: it depends on the degree only).
  const int degree = quadrature_degree > 0 ? quadrature_degree : 2 * m.order + 2;
  const auto ref = geometry::reference_triangle(pk, degree);
  pressure_basis_ = ref.N;
}

std::span<const int> TaylorHoodSpace::velocity(std::size_t e, VelocityComponent c) const {
  const std::size_t npe = velocity_nodes_per_element();
  return {velocity_[c].data() + e * npe, npe};
}

std::span<const int> TaylorHoodSpace::pressure(std::size_t e) const {
  const std::size_t npp = pressure_npe_;
  return {pressure_.data() + e * npp, npp};
}

}  // namespace rc::modes
