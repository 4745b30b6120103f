#include "viscous_fields.hpp"

#include "cluster_fields.hpp"
#include "lagrange_nodes.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {

ModeFields viscous_fields_mesh(const TaylorHoodSpace& space) {
  ModeFields f;
  fill_fields_mesh(space.geometry().mesh(), f);
  return f;
}

ModeFields::Mode viscous_mode_field(const TaylorHoodSpace& space, const ViscousMode& mode) {
  using cd = std::complex<double>;
  const auto& x = mode.vector;
  if (static_cast<int>(x.size()) != space.size())
    throw std::logic_error("viscous_mode_field: the mode's eigenvector was not kept");
  const auto& mesh = space.geometry().mesh();
  const std::size_t n = mesh.nodes.size(), npe = space.velocity_nodes_per_element();
  const auto value = [&](int dof) { return dof >= 0 ? x[dof] : cd(0); };
  // The pressure basis (order k − 1) at the velocity nodes (order k) of the reference triangle.
  const auto Np = geometry::triangle_basis_at(space.order() - 1, geometry::triangle_nodes(space.order()).points);
  const std::size_t npp = space.pressure_nodes_per_element();
  std::vector<cd> Vr(n), Vphi(n), Vz(n), P(n);
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    const auto plus = space.velocity(e, kPlus), minus = space.velocity(e, kMinus), axial = space.velocity(e, kAxial);
    const auto pressure = space.pressure(e);
    for (std::size_t a = 0; a < npe; ++a) {
      const int node = mesh.triangles[e * npe + a];
      const cd up = value(plus[a]), um = value(minus[a]);
      Vr[node] = 0.5 * (up + um);
      Vphi[node] = (up - um) / cd(0, 2);
      Vz[node] = value(axial[a]);
      cd Q = 0;
      for (std::size_t b = 0; b < npp; ++b) Q += Np[a * npp + b] * value(pressure[b]);
      P[node] = cd(0, -1) * Q;  // Q = iP (viscous_forms.hpp)
    }
  }
  ModeFields::Mode m;
  m.lambda = mode.lambda.real();
  m.members = 1;
  m.E_members = mode.residue.real();
  m.a = std::sqrt(mode.residue / 2.0).real();
  m.p.resize(n);
  m.p_imag.resize(n);
  m.V.resize(3 * n);
  m.V_imag.resize(3 * n);
  m.energy_density.resize(n);
  const double scale = 2 * std::numbers::pi * mode.conjugate_norm;
  for (std::size_t i = 0; i < n; ++i) {
    m.p[i] = P[i].real();
    m.p_imag[i] = P[i].imag();
    const cd v[3] = {Vr[i], Vphi[i], Vz[i]};
    for (int c = 0; c < 3; ++c) {
      m.V[3 * i + c] = v[c].real();
      m.V_imag[3 * i + c] = v[c].imag();
    }
    m.energy_density[i] = (std::norm(v[0]) + std::norm(v[1]) + std::norm(v[2])) * mesh.nodes[i][0] / scale;
  }
  return m;
}

}  // namespace rc::modes
