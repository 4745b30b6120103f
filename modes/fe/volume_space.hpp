// The scalar Lagrange finite-element space on a 3-D cavity (tetrahedra, isoparametric): one degree of freedom per
// mesh node except one, where p = 0 (a pressure is defined up to a constant; pinning one node takes the constant
// out of the Neumann stiffness and out of the Poincaré pencil, where it would be an eigenvector for every λ).
#pragma once

#include "volume_mesh.hpp"

#include <span>
#include <vector>

namespace rc::modes {

// Values at the quadrature points of one tetrahedron, in physical coordinates.
struct VolumeQuadrature {
  std::vector<double> x, y, z, w;    // w = reference weight · |det J|
  std::vector<double> N;             // N[q * npe + a]
  std::vector<double> dNx, dNy, dNz; // [q * npe + a]
};

class VolumeSpace {
 public:
  // quadrature_degree = 0 picks 2·order + 1 (curved boundary elements; measured enough: docs/volume.md §1).
  // pin_first_node = false keeps every node a dof: a free surface fixes the pressure's constant itself (docs/volume.md
  // §8), where a pinned node on that surface would be wrong.
  explicit VolumeSpace(geometry::VolumeMesh mesh, int quadrature_degree = 0, bool pin_first_node = true);

  int ndof() const { return ndof_; }
  int order() const { return mesh_.order; }
  int nodes_per_element() const { return mesh_.nodes_per_element; }
  std::size_t num_elements() const { return mesh_.num_tetrahedra(); }
  const geometry::VolumeMesh& mesh() const { return mesh_; }

  // Global dof of each local node of element e; -1 for the pinned node.
  std::span<const int> element_dofs(std::size_t e) const {
    return {dofs_.data() + e * mesh_.nodes_per_element, static_cast<std::size_t>(mesh_.nodes_per_element)};
  }

  // Fills `out` with the quadrature data of element e (reused buffer). Throws on a non-positive Jacobian.
  void quadrature(std::size_t e, VolumeQuadrature& out) const;

 private:
  geometry::VolumeMesh mesh_;
  geometry::ReferenceTetrahedron ref_;
  int ndof_ = 0;
  std::vector<int> dofs_;
};

}  // namespace rc::modes
