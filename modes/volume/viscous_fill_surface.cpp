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

std::array<std::vector<std::complex<double>>, kFillDirections> fill_inputs(const ViscousFillSurface& s,
                                                                         const DirectionFunctionals& rotations,
                                                                         const DirectionFunctionals& translations,
                                                                         const std::array<double, 3>& centroid) {
  const auto& p0 = s.axis_point;
  const std::array<double, 3> d = {centroid[0] - p0[0], centroid[1] - p0[1], centroid[2] - p0[2]};  // c − P0
  // e_k × d for k = x, y, z, and the translations' velocities −e_y, e_x.
  const std::array<std::array<double, 3>, kFillDirections> moved = {{{0, -d[2], d[1]}, {d[2], 0, -d[0]},
                                                                     {-d[1], d[0], 0}, {0, -1, 0}, {1, 0, 0}}};
  const std::size_t n = rotations[0].size();
  std::array<std::vector<std::complex<double>>, kFillDirections> F;
  for (int j = 0; j < kFillDirections; ++j) {
    F[j].assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      double v = j < 3 ? rotations[j][i] : 0.0;
      for (int c = 0; c < 3; ++c) v += moved[j][c] * translations[c][i];
      F[j][i] = v;
    }
  }
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
