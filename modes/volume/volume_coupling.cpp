#include "volume_coupling.hpp"

#include <complex>
#include <stdexcept>

namespace rc::modes {

PressureModeCoupling pressure_mode_coupling(const VolumeSpace& space, const std::array<double, 3>& centroid,
                                            double lambda, const std::vector<double>& p) {
  using C = std::complex<double>;
  const int n = space.ndof(), npe = space.nodes_per_element();
  if (static_cast<int>(p.size()) != 2 * n) throw std::invalid_argument("pressure_mode_coupling: wrong length");
  const C i(0, 1);
  const double D = 4 - lambda * lambda;
  PressureModeCoupling out;
  VolumeQuadrature eq;
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    const auto dofs = space.element_dofs(e);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      C g[3] = {0, 0, 0};  // ∇P
      for (int a = 0; a < npe; ++a) {
        if (dofs[a] < 0) continue;
        const C P(p[dofs[a]], p[n + dofs[a]]);
        g[0] += eq.dNx[q * npe + a] * P; g[1] += eq.dNy[q * npe + a] * P; g[2] += eq.dNz[q * npe + a] * P;
      }
      // (iλ − 2ẑ×) g_h with ẑ × (g_x, g_y) = (−g_y, g_x).
      const C V[3] = {-(i * lambda * g[0] + 2.0 * g[1]) / D, -(i * lambda * g[1] - 2.0 * g[0]) / D, i * g[2] / lambda};
      const double r[3] = {eq.x[q] - centroid[0], eq.y[q] - centroid[1], eq.z[q] - centroid[2]}, w = eq.w[q];
      out.c(0) += w * (-r[2] * V[1] + r[1] * V[2]);  // (e_x × r)·V
      out.c(1) += w * (r[2] * V[0] - r[0] * V[2]);   // (e_y × r)·V
      out.c(2) += w * (-r[1] * V[0] + r[0] * V[1]);  // (e_z × r)·V
      out.norm2 += w * (std::norm(V[0]) + std::norm(V[1]) + std::norm(V[2]));
    }
  }
  return out;
}

}  // namespace rc::modes
