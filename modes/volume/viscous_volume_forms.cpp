#include "viscous_volume_forms.hpp"

#include "block_pencil.hpp"
#include "viscous_fill_surface.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

namespace rc::modes {
namespace {

struct ElementMatrices {
  std::vector<double> m0, k0;    // per pair of local velocity nodes
  std::array<std::vector<double>, 3> b;  // per (pressure node, velocity node): ∫ q ∂_d v
  std::array<std::array<std::vector<double>, 3>, 3> f;  // f[k][d][a]: coupling k on component d of node a
  std::vector<double> n1;        // per velocity node, ∫ N: the translations' functionals (a free surface's directions)
  std::array<std::array<std::vector<double>, 3>, 3> kc;  // with a free surface: kc[d][d′] = ∫ ∂_d′ w ∂_d v (header)
};

void integrate_element(const VolumeTaylorHoodSpace& space, std::size_t e, const std::array<double, 3>& centroid,
                       bool stress_form, VolumeQuadrature& eq, ElementMatrices& out) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  space.geometry().quadrature(e, eq);
  out.m0.assign(npe * npe, 0.0);
  out.k0.assign(npe * npe, 0.0);
  for (auto& b : out.b) b.assign(npp * npe, 0.0);
  for (auto& fk : out.f)
    for (auto& fd : fk) fd.assign(npe, 0.0);
  out.n1.assign(npe, 0.0);
  for (auto& kd : out.kc)
    for (auto& k : kd) k.assign(stress_form ? npe * npe : 0, 0.0);
  const auto& P = space.pressure_basis();
  for (std::size_t q = 0; q < eq.w.size(); ++q) {
    const double w = eq.w[q];
    const double x = eq.x[q] - centroid[0], y = eq.y[q] - centroid[1], z = eq.z[q] - centroid[2];
    const double* N = &eq.N[q * npe];
    const std::array<const double*, 3> dN = {&eq.dNx[q * npe], &eq.dNy[q * npe], &eq.dNz[q * npe]};
    for (int a = 0; a < npe; ++a) {
      const double Nw = N[a] * w;
      out.n1[a] += Nw;
      out.f[0][1][a] -= z * Nw; out.f[0][2][a] += y * Nw;  // e_x × r = (0, −z, y)
      out.f[1][0][a] += z * Nw; out.f[1][2][a] -= x * Nw;  // e_y × r = (z, 0, −x)
      out.f[2][0][a] -= y * Nw; out.f[2][1][a] += x * Nw;  // e_z × r = (−y, x, 0)
      for (int c = 0; c < npe; ++c) {
        out.m0[a * npe + c] += N[a] * N[c] * w;
        out.k0[a * npe + c] += (dN[0][a] * dN[0][c] + dN[1][a] * dN[1][c] + dN[2][a] * dN[2][c]) * w;
        if (stress_form)
          for (int d = 0; d < 3; ++d)
            for (int d2 = 0; d2 < 3; ++d2) out.kc[d][d2][a * npe + c] += dN[d2][a] * dN[d][c] * w;
      }
    }
    const double* Pq = &P[q * npp];
    for (int p = 0; p < npp; ++p)
      for (int a = 0; a < npe; ++a)
        for (int d = 0; d < 3; ++d) out.b[d][p * npe + a] += Pq[p] * dN[d][a] * w;
  }
}

// One element's entries: Re A (B and Bᵀ), Im A (C + Ek K), 𝓜, and the coupling functionals.
void scatter(const VolumeTaylorHoodSpace& space, std::size_t e, const ElementMatrices& em, double ekman,
             Triplets& ar, Triplets& ai, Triplets& mass, DirectionFunctionals& f, DirectionFunctionals& t) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  const std::array<std::span<const int>, 3> u = {space.velocity(e, 0), space.velocity(e, 1), space.velocity(e, 2)};
  const auto p = space.pressure(e);
  for (int a = 0; a < npe; ++a) {
    for (int d = 0; d < 3; ++d) {
      if (u[d][a] < 0) continue;
      for (int k = 0; k < 3; ++k) f[k][u[d][a]] += em.f[k][d][a];
      if (!t[d].empty()) t[d][u[d][a]] += em.n1[a];
    }
    for (int c = 0; c < npe; ++c) {
      const int ac = a * npe + c;
      for (int d = 0; d < 3; ++d) {
        mass.add(u[d][a], u[d][c], em.m0[ac]);
        ai.add(u[d][a], u[d][c], ekman * em.k0[ac]);
      }
      ai.add(u[0][a], u[1][c], -2 * em.m0[ac]);  // C: test x, field y
      ai.add(u[1][a], u[0][c], 2 * em.m0[ac]);   //    test y, field x
      if (!em.kc[0][0].empty())
        for (int d = 0; d < 3; ++d)
          for (int d2 = 0; d2 < 3; ++d2) ai.add(u[d][a], u[d2][c], ekman * em.kc[d][d2][ac]);
    }
  }
  for (int q = 0; q < npp; ++q)
    for (int a = 0; a < npe; ++a)
      for (int d = 0; d < 3; ++d) {
        const double b = em.b[d][q * npe + a];
        ar.add(p[q], u[d][a], b);
        ar.add(u[d][a], p[q], b);
      }
}

// The five directions' inputs and outputs (viscous_fill_surface.hpp) from the whole mesh's functionals.
void add_fill_directions(const ViscousFillSurface& surface, const DirectionFunctionals& rotations,
                         const DirectionFunctionals& translations, const std::array<double, 3>& centroid,
                         ViscousVolumeForms& out) {
  for (auto& Fj : fill_inputs(surface, rotations, translations, centroid)) {
    out.fill_inputs.push_back(block_vector(out.forms.A, Fj));
    for (auto& v : Fj) v = std::conj(v);
    out.fill_outputs.push_back(block_vector(out.forms.A, Fj));
  }
  out.axis_point = surface.axis_point;
  out.surface_radius = surface.surface.radius();
}

}  // namespace

ViscousVolumeForms assemble_viscous_volume_forms(const VolumeTaylorHoodSpace& space, const std::array<double, 3>& centroid,
                                                 double ekman, MPI_Comm comm) {
  if (!(ekman >= 0)) throw std::runtime_error("the Ekman number must be >= 0");
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::size_t ne = space.num_elements();
  const std::size_t first = ne * rank / ranks, last = ne * (rank + 1) / ranks;
  const bool fill = space.free_surface();
  Triplets ar, ai, mass;
  std::optional<ViscousFillSurface> surface;
  if (fill) {
    surface.emplace(number_fill_surface(space, centroid, space.size()));
    if (rank == 0) add_fill_surface_terms(*surface, ar, mass);
  }
  const int n = space.size() + (fill ? surface->count : 0);
  DirectionFunctionals f, f_all, t, t_all;  // rotations about the centroid; translations (a free surface's only)
  for (auto* v : {&f, &f_all})
    for (auto& vk : *v) vk.assign(n, 0.0);
  if (fill)
    for (auto* v : {&t, &t_all})
      for (auto& vk : *v) vk.assign(n, 0.0);
  VolumeQuadrature eq;
  ElementMatrices em;
  for (std::size_t e = first; e < last; ++e) {
    integrate_element(space, e, centroid, fill, eq, em);
    scatter(space, e, em, ekman, ar, ai, mass, f, t);
  }
  for (int k = 0; k < 3; ++k) {
    MPI_Allreduce(f[k].data(), f_all[k].data(), n, MPI_DOUBLE, MPI_SUM, comm);
    if (fill) MPI_Allreduce(t[k].data(), t_all[k].data(), n, MPI_DOUBLE, MPI_SUM, comm);
  }

  ViscousVolumeForms out;
  ViscousForms& forms = out.forms;
  forms.complex_size = n;
  forms.A = block_operator(comm, n, ar, ai, mass);
  forms.M = block_mass(comm, n, mass);
  forms.iM = block_imaginary_mass(comm, n, mass);
  for (int k = 0; k < 3; ++k) out.couplings[k] = block_vector(forms.A, f_all[k]);
  forms.coupling = block_vector(forms.A, f_all[0]);
  forms.real_slots = block_vector(forms.A, std::vector<double>(n, 1.0));
  std::vector<double> velocity(n, 0.0);
  std::fill(velocity.begin(), velocity.begin() + space.velocity_dofs(), 1.0);  // the velocity's unknowns come first
  out.velocity_slots = block_vector(forms.A, velocity);
  petsc_check(MatCreateVecs(forms.M, forms.mass_diagonal.out(), nullptr), "MatCreateVecs");
  petsc_check(MatGetDiagonal(forms.M, forms.mass_diagonal), "MatGetDiagonal");
  if (fill) add_fill_directions(*surface, f_all, t_all, centroid, out);
  return out;
}

}  // namespace rc::modes
