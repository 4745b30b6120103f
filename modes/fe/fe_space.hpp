// The scalar Lagrange finite-element space on the meridian half-section for azimuthal number m >= 1:
// one degree of freedom per mesh node except the nodes on the axis, where p = 0 (docs/physics.md §2: p = 0 on the
// axis for m >= 1). Geometry is isoparametric: the same basis maps the reference triangle.
#pragma once

#include "meridian_mesh.hpp"

#include <span>
#include <vector>

namespace rc::modes {

// Values at the quadrature points of one element, in physical coordinates.
struct ElementQuadrature {
  std::vector<double> r, z, w;  // w = reference weight * |det J| (the measure dr dz, no r factor)
  std::vector<double> N;        // N[q * npe + a]
  std::vector<double> dNr, dNz; // d/dr, d/dz of basis a at point q: [q * npe + a]
};

class FESpace {
 public:
  // quadrature_degree = 0 picks 2*order + 2, enough for the r-weighted forms on curved elements.
  FESpace(geometry::MeridianMesh mesh, int quadrature_degree = 0);

  int ndof() const { return ndof_; }
  int order() const { return mesh_.order; }
  int nodes_per_element() const { return mesh_.nodes_per_element; }
  std::size_t num_elements() const { return mesh_.num_triangles(); }
  const geometry::MeridianMesh& mesh() const { return mesh_; }

  // Global dof of each local node of element e; -1 for a node on the axis (constrained to zero).
  std::span<const int> element_dofs(std::size_t e) const {
    return {dofs_.data() + e * mesh_.nodes_per_element, static_cast<std::size_t>(mesh_.nodes_per_element)};
  }
  // Node index of each dof (for output of fields).
  const std::vector<int>& dof_nodes() const { return dof_nodes_; }

  // Fills `out` with the quadrature data of element e (reused buffer: no allocation after the first call).
  // Throws if the isoparametric map is not orientation-preserving at a quadrature point.
  void quadrature(std::size_t e, ElementQuadrature& out) const;

 private:
  geometry::MeridianMesh mesh_;
  geometry::ReferenceTriangle ref_;
  int ndof_ = 0;
  std::vector<int> dofs_;       // per element, per local node
  std::vector<int> dof_nodes_;  // per dof
};

}  // namespace rc::modes
