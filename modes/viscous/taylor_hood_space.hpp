// The Taylor–Hood space P_k / P_{k−1} of the m = 1 viscous problem on the meridian half-section
// (docs/viscous.md, "Discretisation"). The velocity is stored in circular components
//   u+ = V_r + i V_φ,   u− = V_r − i V_φ,   u_z = V_z,
// each a Lagrange field of the mesh's order k; the pressure is continuous of order k − 1 on the same
// isoparametric triangles. Essential conditions are built into the numbering (constrained values get no dof):
//   wall: no slip, u+ = u− = u_z = 0;
//   axis: u+ = u_z = 0 and p = 0 (an m = 1 field is smooth on the axis only with V_φ = i V_r, V_z = 0, p = 0;
//         u− = 2 V_r stays free).
#pragma once

#include "fe_space.hpp"

#include <array>
#include <span>
#include <vector>

namespace rc::modes {

enum VelocityComponent { kPlus = 0, kMinus = 1, kAxial = 2 };

class TaylorHoodSpace {
 public:
  // Throws std::runtime_error if the mesh's order is below 2 (P_{k−1} needs k ≥ 2).
  TaylorHoodSpace(geometry::MeridianMesh mesh, int quadrature_degree = 0);

  // Unknowns are numbered velocity first (u+, u−, u_z blocks), then pressure.
  int size() const { return velocity_dofs_ + pressure_dofs_; }
  int velocity_dofs() const { return velocity_dofs_; }
  int pressure_dofs() const { return pressure_dofs_; }
  int order() const { return geometry_.order(); }
  std::size_t num_elements() const { return geometry_.num_elements(); }
  int velocity_nodes_per_element() const { return geometry_.nodes_per_element(); }
  int pressure_nodes_per_element() const { return pressure_npe_; }
  const FESpace& geometry() const { return geometry_; }

  // Global unknown of each local velocity node of element e for one component; −1 where constrained to zero.
  std::span<const int> velocity(std::size_t e, VelocityComponent c) const;
  // Global unknown of each local pressure node of element e; −1 on the axis.
  std::span<const int> pressure(std::size_t e) const;
  // Pressure basis values at the quadrature points of FESpace::quadrature: Np[q * pressure_npe + b].
  const std::vector<double>& pressure_basis() const { return pressure_basis_; }
  // Triangles whose three vertices all lie on the wall or the axis. Taylor–Hood is stable only when every
  // triangle has an interior vertex; each such triangle can carry a spurious pressure mode.
  int boundary_locked_triangles() const { return boundary_locked_; }

 private:
  FESpace geometry_;
  int velocity_dofs_ = 0, pressure_dofs_ = 0, pressure_npe_ = 0, boundary_locked_ = 0;
  std::array<std::vector<int>, 3> velocity_;  // per component: per element, per local node
  std::vector<int> pressure_;                 // per element, per local pressure node
  std::vector<double> pressure_basis_;
};

}  // namespace rc::modes
