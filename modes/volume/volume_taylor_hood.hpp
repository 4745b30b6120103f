// The Taylor–Hood space P_k / P_{k−1} of the viscous fluid in a 3-D cavity (docs/volume.md §7): the velocity's
// Cartesian components V_x, V_y, V_z, each a Lagrange field of the mesh's order k on the isoparametric tetrahedra, the
// pressure continuous of order k − 1 on the same elements. No slip is built into the numbering: every node on the wall
// (a face of one tetrahedron only) carries no velocity unknown. The pressure is defined up to a constant in a closed
// cavity; one pressure node (the first numbered) is pinned to zero to take the constant out.
// A partially filled tank (the mesh has a free surface, docs/volume.md §8) is stress-free there: the surface's nodes
// off the walls keep their velocity unknowns (the contact line, on a wall too, has none), and no pressure node is
// pinned (the surface fixes the pressure's constant). Its geometry() then numbers a dof on every node (dof = node).
#pragma once

#include "volume_space.hpp"

#include <array>
#include <span>
#include <vector>

namespace rc::modes {

class VolumeTaylorHoodSpace {
 public:
  // Throws std::runtime_error if the mesh's order is below 2 or it has no free velocity or pressure unknown.
  explicit VolumeTaylorHoodSpace(geometry::VolumeMesh mesh, int quadrature_degree = 0);

  // Unknowns: V_x, V_y, V_z blocks, then pressure.
  int size() const { return velocity_dofs_ + pressure_dofs_; }
  int velocity_dofs() const { return velocity_dofs_; }
  int pressure_dofs() const { return pressure_dofs_; }
  int order() const { return geometry_.order(); }
  std::size_t num_elements() const { return geometry_.num_elements(); }
  int velocity_nodes_per_element() const { return geometry_.nodes_per_element(); }
  int pressure_nodes_per_element() const { return pressure_npe_; }
  const VolumeSpace& geometry() const { return geometry_; }
  int wall_nodes() const { return wall_nodes_; }
  bool free_surface() const { return geometry_.mesh().free_surface_radius > 0; }

  // Global unknown of each local velocity node of element e for component c (0, 1, 2 = x, y, z); −1 on the wall.
  std::span<const int> velocity(std::size_t e, int c) const;
  // Global unknown of each local pressure node of element e; −1 for the pinned node.
  std::span<const int> pressure(std::size_t e) const;
  // Pressure basis values at the quadrature points of VolumeSpace::quadrature: Np[q * pressure_npe + b].
  const std::vector<double>& pressure_basis() const { return pressure_basis_; }

 private:
  VolumeSpace geometry_;
  int velocity_dofs_ = 0, pressure_dofs_ = 0, pressure_npe_ = 0, wall_nodes_ = 0;
  std::array<std::vector<int>, 3> velocity_;  // per component: per element, per local node
  std::vector<int> pressure_;  // per element, per local pressure node
  std::vector<double> pressure_basis_;
};

}  // namespace rc::modes
