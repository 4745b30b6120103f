#include "fe_space.hpp"

#include <stdexcept>
#include <string>

namespace rc::modes {

FESpace::FESpace(geometry::MeridianMesh mesh, int quadrature_degree) : mesh_(std::move(mesh)) {
  if (quadrature_degree <= 0) quadrature_degree = 2 * mesh_.order + 2;
  ref_ = geometry::reference_triangle(mesh_.order, quadrature_degree);
  std::vector<int> node_dof(mesh_.nodes.size(), 0);
  for (int n : mesh_.axis_nodes) node_dof[n] = -1;
  for (std::size_t n = 0; n < node_dof.size(); ++n) {
    if (node_dof[n] == -1) continue;
    node_dof[n] = ndof_++;
    dof_nodes_.push_back(static_cast<int>(n));
  }
  dofs_.resize(mesh_.triangles.size());
  for (std::size_t i = 0; i < mesh_.triangles.size(); ++i) dofs_[i] = node_dof[mesh_.triangles[i]];
  if (ndof_ == 0) throw std::runtime_error("the mesh has no degree of freedom off the axis");
}

void FESpace::quadrature(std::size_t e, ElementQuadrature& out) const {
  const int npe = mesh_.nodes_per_element;
  const std::size_t nq = ref_.weights.size();
  out.r.assign(nq, 0.0);
  out.z.assign(nq, 0.0);
  out.w.resize(nq);
  out.N = ref_.N;
  out.dNr.resize(nq * npe);
  out.dNz.resize(nq * npe);
  const int* nodes = mesh_.triangles.data() + e * npe;
  for (std::size_t q = 0; q < nq; ++q) {
    // Isoparametric map (u, v) -> (r, z) and its Jacobian J = [[r_u, r_v], [z_u, z_v]].
    double ru = 0, rv = 0, zu = 0, zv = 0;
    for (int a = 0; a < npe; ++a) {
      const auto& x = mesh_.nodes[nodes[a]];
      const double Na = ref_.N[q * npe + a];
      const double du = ref_.dN[(q * npe + a) * 2], dv = ref_.dN[(q * npe + a) * 2 + 1];
      out.r[q] += Na * x[0];
      out.z[q] += Na * x[1];
      ru += du * x[0]; rv += dv * x[0];
      zu += du * x[1]; zv += dv * x[1];
    }
    const double det = ru * zv - rv * zu;
    if (!(det > 0))
      throw std::runtime_error("element " + std::to_string(e) + " is inverted or degenerate (det J = " +
                               std::to_string(det) + ")");
    out.w[q] = ref_.weights[q] * det;
    for (int a = 0; a < npe; ++a) {
      const double du = ref_.dN[(q * npe + a) * 2], dv = ref_.dN[(q * npe + a) * 2 + 1];
      // grad_x N = J^{-T} grad_u N
      out.dNr[q * npe + a] = (zv * du - zu * dv) / det;
      out.dNz[q * npe + a] = (-rv * du + ru * dv) / det;
    }
  }
}

}  // namespace rc::modes
