#include "volume_space.hpp"

#include <stdexcept>
#include <string>

namespace rc::modes {

VolumeSpace::VolumeSpace(geometry::VolumeMesh mesh, int quadrature_degree, bool pin_first_node)
    : mesh_(std::move(mesh)),
      ref_(geometry::reference_tetrahedron(mesh_.order, quadrature_degree > 0 ? quadrature_degree : 2 * mesh_.order + 1)) {
  if (mesh_.nodes.size() < 2) throw std::runtime_error("3-D mesh with fewer than two nodes");
  const int pinned = pin_first_node ? 1 : 0;
  ndof_ = static_cast<int>(mesh_.nodes.size()) - pinned;
  dofs_.reserve(mesh_.tetrahedra.size());
  for (int node : mesh_.tetrahedra) dofs_.push_back(node - pinned);  // a pinned node 0: dof -1
}

void VolumeSpace::quadrature(std::size_t e, VolumeQuadrature& out) const {
  const int npe = mesh_.nodes_per_element;
  const std::size_t nq = ref_.weights.size();
  out.x.assign(nq, 0); out.y.assign(nq, 0); out.z.assign(nq, 0); out.w.resize(nq);
  out.N.resize(nq * npe); out.dNx.resize(nq * npe); out.dNy.resize(nq * npe); out.dNz.resize(nq * npe);
  const int* v = &mesh_.tetrahedra[e * npe];
  for (std::size_t q = 0; q < nq; ++q) {
    double J[3][3] = {};  // J[c][d] = d x_c / d u_d
    for (int a = 0; a < npe; ++a) {
      const auto& X = mesh_.nodes[v[a]];
      const double Na = ref_.N[q * npe + a];
      out.x[q] += Na * X[0]; out.y[q] += Na * X[1]; out.z[q] += Na * X[2];
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d) J[c][d] += X[c] * ref_.dN[(q * npe + a) * 3 + d];
    }
    // Inverse by cofactors: K = J⁻¹, K[d][c] = d u_d / d x_c.
    const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                       J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                       J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    if (!(det > 0)) throw std::runtime_error("3-D element " + std::to_string(e) + " is inverted at a quadrature point");
    double K[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        K[i][j] = (J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1]) / det;
      }
    out.w[q] = ref_.weights[q] * det;
    for (int a = 0; a < npe; ++a) {
      const double* g = &ref_.dN[(q * npe + a) * 3];
      out.N[q * npe + a] = ref_.N[q * npe + a];
      out.dNx[q * npe + a] = g[0] * K[0][0] + g[1] * K[1][0] + g[2] * K[2][0];
      out.dNy[q * npe + a] = g[0] * K[0][1] + g[1] * K[1][1] + g[2] * K[2][1];
      out.dNz[q * npe + a] = g[0] * K[0][2] + g[1] * K[1][2] + g[2] * K[2][2];
    }
  }
}

}  // namespace rc::modes
