#include "volume_coupling.hpp"

#include <stdexcept>

namespace rc::modes {

PressureModeCoupling pressure_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            double lambda, const std::vector<double>& p) {
  return combined_mode_coupling(space, centroid, {PressureMember{lambda, &p, 1.0}});
}

PressureModeCoupling combined_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            const std::vector<PressureMember>& members) {
  using C = std::complex<double>;
  const int n = space.ndof(), npe = space.nodes_per_element();
  for (const auto& m : members)
    if (!m.p || static_cast<int>(m.p->size()) != 2 * n)
      throw std::invalid_argument("pressure_mode_coupling: wrong length");
  PressureModeCoupling out;
  VolumeQuadrature eq;
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      Eigen::Vector3cd V = Eigen::Vector3cd::Zero();
      for (const auto& m : members) {
        Eigen::Vector3cd g = Eigen::Vector3cd::Zero();  // ∇P
        for (int a = 0; a < npe; ++a) {
          if (dofs[a] < 0) continue;
          const C P((*m.p)[dofs[a]], (*m.p)[n + dofs[a]]);
          g += P * Eigen::Vector3cd(eq.dNx[q * npe + a], eq.dNy[q * npe + a], eq.dNz[q * npe + a]);
        }
        V += m.weight * velocity_from_pressure_gradient(m.lambda, g);
      }
      const double r[3] = {eq.x[q] - centroid[0], eq.y[q] - centroid[1], eq.z[q] - centroid[2]}, w = eq.w[q];
      out.c(0) += w * (-r[2] * V(1) + r[1] * V(2));  // (e_x × r)·V
      out.c(1) += w * (r[2] * V(0) - r[0] * V(2));   // (e_y × r)·V
      out.c(2) += w * (-r[1] * V(0) + r[0] * V(1));  // (e_z × r)·V
      out.norm2 += w * V.squaredNorm();
    }
  }
  return out;
}

}  // namespace rc::modes
