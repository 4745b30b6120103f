#include "volume_taylor_hood.hpp"

#include "partial_volume.hpp"
#include "tetrahedron_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rc::modes {
namespace {

// A pressure node is identified across elements by its barycentric lattice weights on the element's vertices,
// written with global vertex numbers and sorted (as the meridian space does, taylor_hood_space.cpp).
using NodeKey = std::vector<std::pair<int, int>>;

NodeKey node_key(const int* vertices, const std::array<double, 3>& uvw, int order) {
  const auto weight = geometry::tetrahedron_lattice(uvw, order);
  NodeKey key;
  for (int v = 0; v < 4; ++v)
    if (weight[v] > 0) key.emplace_back(vertices[v], weight[v]);
  std::sort(key.begin(), key.end());
  return key;
}

// The mesh nodes on the wall: every node of a face that one tetrahedron alone has (the local nodes whose barycentric
// weight on the face's opposite vertex is zero), except a partially filled tank's free-surface faces (every node on
// the cylinder ρ = b, as volume_free_surface.cpp finds them): stress-free, not no-slip.
std::vector<char> nodes_on_wall(const geometry::VolumeMesh& mesh) {
  const int npe = mesh.nodes_per_element;
  const auto nodes = geometry::tetrahedron_nodes(mesh.order);
  std::vector<char> wall(mesh.nodes.size(), 0);
  std::vector<int> face;
  for (const auto& [e, o] : geometry::wall_faces(mesh)) {
    face.clear();
    for (int a = 0; a < npe; ++a)
      if (geometry::tetrahedron_lattice(nodes.points[a], mesh.order)[o] == 0) face.push_back(mesh.tetrahedra[e * npe + a]);
    const bool free = mesh.free_surface_radius > 0 && std::all_of(face.begin(), face.end(), [&](int n) {
      return geometry::on_free_surface(mesh.nodes[n], mesh.free_surface_radius, mesh.spin_axis);
    });
    if (!free)
      for (int n : face) wall[n] = 1;
  }
  return wall;
}

}  // namespace

VolumeTaylorHoodSpace::VolumeTaylorHoodSpace(geometry::VolumeMesh mesh, int quadrature_degree)
    : geometry_([&] {
        const bool pin = !(mesh.free_surface_radius > 0);  // read before the move
        return VolumeSpace(std::move(mesh), quadrature_degree, pin);
      }()) {
  const auto& m = geometry_.mesh();
  if (m.order < 2)
    throw std::runtime_error("the viscous solver needs elements of order >= 2 (Taylor-Hood P_k/P_(k-1)); got " +
                             std::to_string(m.order));
  const int npe = m.nodes_per_element;
  const std::size_t ne = m.num_tetrahedra();
  const std::vector<char> wall = nodes_on_wall(m);
  wall_nodes_ = static_cast<int>(std::count(wall.begin(), wall.end(), 1));
  for (int c = 0; c < 3; ++c) {
    std::vector<int> node_dof(m.nodes.size(), -1);
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
      if (!wall[n]) node_dof[n] = velocity_dofs_++;
    velocity_[c].resize(ne * npe);
    for (std::size_t i = 0; i < ne * npe; ++i) velocity_[c][i] = node_dof[m.tetrahedra[i]];
  }

  const int pk = m.order - 1;
  const auto nodes = geometry::tetrahedron_nodes(pk);
  pressure_npe_ = nodes.nodes_per_element;
  std::map<NodeKey, int> numbered;
  pressure_.resize(ne * pressure_npe_);
  const int pinned = free_surface() ? 0 : 1;  // pressure nodes numbered from 0; node 0 is the pinned one, if any
  int next = 0;
  for (std::size_t e = 0; e < ne; ++e)
    for (int b = 0; b < pressure_npe_; ++b) {
      auto [it, is_new] = numbered.try_emplace(node_key(&m.tetrahedra[e * npe], nodes.points[b], pk), next);
      if (is_new) ++next;
      pressure_[e * pressure_npe_ + b] = it->second < pinned ? -1 : velocity_dofs_ + it->second - pinned;
    }
  pressure_dofs_ = next - pinned;
  if (velocity_dofs_ == 0 || pressure_dofs_ <= 0)
    throw std::runtime_error("the 3-D mesh has no free velocity or pressure unknown (too coarse for order " +
                             std::to_string(m.order) + ")");
  const int degree = quadrature_degree > 0 ? quadrature_degree : 2 * m.order + 1;
  pressure_basis_ = geometry::reference_tetrahedron(pk, degree).N;
}

std::span<const int> VolumeTaylorHoodSpace::velocity(std::size_t e, int c) const {
  const std::size_t npe = velocity_nodes_per_element();
  return {velocity_[c].data() + e * npe, npe};
}

std::span<const int> VolumeTaylorHoodSpace::pressure(std::size_t e) const {
  const std::size_t npp = pressure_npe_;
  return {pressure_.data() + e * npp, npp};
}

}  // namespace rc::modes
