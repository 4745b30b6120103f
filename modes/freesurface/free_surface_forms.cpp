#include "free_surface_forms.hpp"

#include "surface_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {

namespace {

// dof of each mesh node (−1 on the axis, which a liquid with a free surface does not reach).
std::vector<int> node_dofs(const FESpace& space) {
  std::vector<int> out(space.mesh().nodes.size(), -1);
  for (int d = 0; d < space.ndof(); ++d) out[space.dof_nodes()[d]] = d;
  return out;
}

// g1(q) = ∫∫ (q + r q_r) dr dz over the liquid.
Eigen::VectorXd offset_functional(const FESpace& space) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(space.ndof());
  const int npe = space.nodes_per_element();
  ElementQuadrature eq;
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q)
      for (int a = 0; a < npe; ++a)
        if (dofs[a] >= 0) g(dofs[a]) += (eq.N[q * npe + a] + eq.r[q] * eq.dNr[q * npe + a]) * eq.w[q];
  }
  return g;
}

}  // namespace

FreeSurfaceForms assemble_free_surface_forms(const FESpace& space, double centroid_z) {
  const auto& mesh = space.mesh();
  if (mesh.free_edges.empty()) throw std::runtime_error("the mesh has no free surface");
  constexpr double pi = std::numbers::pi;
  FreeSurfaceForms F;
  const int n = space.ndof(), p = mesh.order, nn = p + 1;
  const double b = mesh.free_radius;
  F.radius = b;
  F.f3 = F.e1 = Eigen::VectorXd::Zero(n);
  const auto dof = node_dofs(space);
  const geometry::ReferenceEdge edge = geometry::reference_edge(p, 2 * p + 2);
  std::vector<Eigen::Triplet<double>> entries;
  double z0 = 0, z1 = 0, z2 = 0;
  for (const FreeSurfacePoint& q : free_surface_points(mesh, edge)) {
    const double w = q.w, zp = q.z - centroid_z;
    z0 += w; z1 += zp * w; z2 += zp * zp * w;
    for (int a = 0; a < nn; ++a) {
      const int i = dof[q.nodes[a]];
      F.f3(i) += b * zp * q.N[a] * w;
      F.e1(i) += b * q.N[a] * w;
      for (int c = 0; c < nn; ++c) entries.emplace_back(i, dof[q.nodes[c]], q.N[a] * q.N[c] * w);
    }
  }
  for (int node : mesh.free_edges) F.surface_dofs.push_back(dof[node]);
  F.S.resize(n, n);
  F.S.setFromTriplets(entries.begin(), entries.end());
  std::sort(F.surface_dofs.begin(), F.surface_dofs.end());
  F.surface_dofs.erase(std::unique(F.surface_dofs.begin(), F.surface_dofs.end()), F.surface_dofs.end());
  F.K0 = pi * b * b * z0;
  F.K1 = pi * b * b * z1;
  F.K2 = pi * b * b * z2;
  F.g1 = offset_functional(space);
  return F;
}

Eigen::SparseMatrix<double> to_eigen(Mat A) {
  PetscInt rows = 0, cols = 0;
  petsc_check(MatGetSize(A, &rows, &cols), "MatGetSize");
  std::vector<Eigen::Triplet<double>> entries;
  for (PetscInt i = 0; i < rows; ++i) {
    PetscInt nc = 0;
    const PetscInt* c = nullptr;
    const PetscScalar* v = nullptr;
    petsc_check(MatGetRow(A, i, &nc, &c, &v), "MatGetRow");
    for (PetscInt k = 0; k < nc; ++k) entries.emplace_back(i, c[k], v[k]);
    petsc_check(MatRestoreRow(A, i, &nc, &c, &v), "MatRestoreRow");
  }
  Eigen::SparseMatrix<double> out(rows, cols);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

Eigen::VectorXd to_eigen(Vec v) {
  PetscInt n = 0;
  petsc_check(VecGetSize(v, &n), "VecGetSize");
  const PetscScalar* a = nullptr;
  petsc_check(VecGetArrayRead(v, &a), "VecGetArrayRead");
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(a, n);
  petsc_check(VecRestoreArrayRead(v, &a), "VecRestoreArrayRead");
  return out;
}

}  // namespace rc::modes
