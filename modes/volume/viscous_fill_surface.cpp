#include "viscous_fill_surface.hpp"

#include <cmath>
#include <stdexcept>

namespace rc::modes {
namespace {

// The surface's outward unit normal from the spin axis at x (e_ρ: the direction η is measured along).
std::array<double, 2> radial(const ViscousFillSurface& s, const std::array<double, 3>& x) {
  const double dx = x[0] - s.axis_point[0], dy = x[1] - s.axis_point[1], rho = std::hypot(dx, dy);
  return {dx / rho, dy / rho};
}

// The direction j's surface part ψ_j (b times its η: χ_x = xz, χ_y = yz, χ_z = −(x² + y²), then r_x, r_y; r from P0).
double surface_part(int j, const std::array<double, 3>& x, const std::array<double, 3>& p0) {
  const double rx = x[0] - p0[0], ry = x[1] - p0[1], rz = x[2] - p0[2];
  switch (j) {
    case 0: return rx * rz;
    case 1: return ry * rz;
    case 2: return -(rx * rx + ry * ry);
    case 3: return rx;
    default: return ry;
  }
}

// The direction j's velocity part at r (from P0): e_k × r, then e_x × ẑ = −e_y and e_y × ẑ = e_x.
std::array<double, 3> velocity_part(int j, double rx, double ry, double rz) {
  switch (j) {
    case 0: return {0, -rz, ry};
    case 1: return {rz, 0, -rx};
    case 2: return {-ry, rx, 0};
    case 3: return {0, -1, 0};
    default: return {1, 0, 0};
  }
}

}  // namespace

ViscousFillSurface number_fill_surface(const VolumeTaylorHoodSpace& space, const std::array<double, 3>& centroid,
                                       int first) {
  ViscousFillSurface s{VolumeFreeSurface(space.geometry()), {}, {}, first, 0, {}};
  const auto& m = space.geometry().mesh();
  s.axis_point = {m.spin_axis[0], m.spin_axis[1], centroid[2]};
  const int npe = space.velocity_nodes_per_element();
  for (auto& v : s.velocity) v.assign(m.nodes.size(), -1);
  for (std::size_t e = 0; e < space.num_elements(); ++e)
    for (int c = 0; c < 3; ++c) {
      const auto u = space.velocity(e, c);
      for (int a = 0; a < npe; ++a) s.velocity[c][m.tetrahedra[e * npe + a]] = u[a];
    }
  // The surface's dofs are mesh nodes (space.geometry() pins none on a mesh with a free surface).
  const auto& dofs = s.surface.dofs();
  s.eta.assign(dofs.size(), -1);
  for (std::size_t i = 0; i < dofs.size(); ++i)
    if (s.velocity[0][dofs[i]] >= 0) s.eta[i] = first + s.count++;
  if (s.count == 0) throw std::runtime_error("the free surface has no node off the walls (mesh too coarse)");
  return s;
}

void add_fill_surface_terms(const ViscousFillSurface& s, Triplets& ar, Triplets& mass) {
  const double b = s.surface.radius();
  const auto& dofs = s.surface.dofs();
  for (const auto& pt : s.surface.points()) {
    const auto n = radial(s, pt.x);
    for (std::size_t a = 0; a < pt.N.size(); ++a) {
      const int ea = s.eta[pt.surface[a]];
      if (ea < 0) continue;
      for (std::size_t c = 0; c < pt.N.size(); ++c) {
        const double w = b * pt.N[a] * pt.N[c] * pt.w;
        mass.add(ea, s.eta[pt.surface[c]], w);
        for (int d = 0; d < 2; ++d) {  // V·e_ρ: e_ρ has no z part
          const int u = s.velocity[d][dofs[pt.surface[c]]];
          ar.add(ea, u, n[d] * w);
          ar.add(u, ea, n[d] * w);
        }
      }
    }
  }
}

std::array<std::vector<std::complex<double>>, kFillDirections> fill_inputs(const VolumeTaylorHoodSpace& space,
                                                                         const ViscousFillSurface& s, int n,
                                                                         std::size_t first_element,
                                                                         std::size_t last_element, bool surface_too) {
  std::array<std::vector<std::complex<double>>, kFillDirections> F;
  for (auto& f : F) f.assign(n, 0.0);
  const auto& p0 = s.axis_point;
  const int npe = space.velocity_nodes_per_element();
  VolumeQuadrature eq;
  for (std::size_t e = first_element; e < last_element; ++e) {
    space.geometry().quadrature(e, eq);
    const std::array<std::span<const int>, 3> u = {space.velocity(e, 0), space.velocity(e, 1), space.velocity(e, 2)};
    for (std::size_t q = 0; q < eq.w.size(); ++q)
      for (int j = 0; j < kFillDirections; ++j) {
        const auto v = velocity_part(j, eq.x[q] - p0[0], eq.y[q] - p0[1], eq.z[q] - p0[2]);
        for (int a = 0; a < npe; ++a)
          for (int d = 0; d < 3; ++d)
            if (u[d][a] >= 0 && v[d] != 0) F[j][u[d][a]] += v[d] * eq.N[q * npe + a] * eq.w[q];
      }
  }
  if (!surface_too) return F;
  // The surface parts: +i ∫_Σ ζ (ψ_j − ψ̄_j) dS (a constant surface pressure moves nothing).
  const std::complex<double> I(0, 1);
  for (int j = 0; j < kFillDirections; ++j) {
    const double mean = s.surface.integral([&](const auto& x) { return surface_part(j, x, p0); }) / s.surface.area();
    for (const auto& pt : s.surface.points()) {
      const double psi = surface_part(j, pt.x, p0) - mean;
      for (std::size_t a = 0; a < pt.N.size(); ++a)
        if (const int ea = s.eta[pt.surface[a]]; ea >= 0) F[j][ea] += I * psi * pt.N[a] * pt.w;
    }
  }
  return F;
}

}  // namespace rc::modes
