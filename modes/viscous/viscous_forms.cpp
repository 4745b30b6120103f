#include "viscous_forms.hpp"

#include "block_pencil.hpp"
#include "surface_quadrature.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <stdexcept>
#include <vector>

namespace rc::modes {
namespace {

struct ElementMatrices {
  // Per pair of local velocity nodes: M0, K0, K1, K2; per (pressure node, velocity node): the three B rows.
  std::vector<double> m0, k0, k1, k2, bp, bm, bz;
  std::vector<double> fm, fz;  // coupling functional on u− and u_z
  std::vector<double> gm;      // its part per unit offset of the joint below the centroid, on u− (header)
  // With a free surface: the stress form's cross term (header), per (test component, field component) block.
  std::vector<double> t;
};

// The cross term ∫∫ ∇V : (∇W̄)ᵀ r dr dz that turns the vector Laplacian's K into the stress form 2∫∫ D(V) : D(W̄)
// (header), in circular components; its coefficients (derived with sympy from the cylindrical ∇V of an m = 1 field,
// which also gives back K's) for field (j, its value or r-, z-derivative) and test (i, likewise):
//   (+,+): u w/r² − (u w_r + u_r w)/(2r) + u_r w_r/4      (+,−): u+ w−_r/(2r) + u+_r w−_r/4   and its transpose
//   (−,−): u_r w_r/4        (z,±): ∓ u_z w±_z/(2r) + u_z,r w±_z/2   and its transpose        (z,z): u_z,z w_z,z
void add_stress_cross_term(int npe, double r, double w, const double* N, const double* Nr, const double* Nz,
                           std::vector<double>& t) {
  const auto at = [&](int ci, int cj, int a, int b) -> double& { return t[((ci * 3 + cj) * npe + a) * npe + b]; };
  const double rw = r * w;
  for (int a = 0; a < npe; ++a)      // test node
    for (int b = 0; b < npe; ++b) {  // field node
      at(kPlus, kPlus, a, b) += (N[b] * N[a] / (r * r) - (N[b] * Nr[a] + Nr[b] * N[a]) / (2 * r) + Nr[b] * Nr[a] / 4) * rw;
      at(kMinus, kPlus, a, b) += (N[b] * Nr[a] / (2 * r) + Nr[b] * Nr[a] / 4) * rw;   // field +, test −
      at(kPlus, kMinus, a, b) += (Nr[b] * N[a] / (2 * r) + Nr[b] * Nr[a] / 4) * rw;   // field −, test +
      at(kMinus, kMinus, a, b) += Nr[b] * Nr[a] / 4 * rw;
      at(kPlus, kAxial, a, b) += (-N[b] * Nz[a] / (2 * r) + Nr[b] * Nz[a] / 2) * rw;  // field z, test +
      at(kMinus, kAxial, a, b) += (N[b] * Nz[a] / (2 * r) + Nr[b] * Nz[a] / 2) * rw;  // field z, test −
      at(kAxial, kPlus, a, b) += (-Nz[b] * N[a] / (2 * r) + Nz[b] * Nr[a] / 2) * rw;  // field +, test z
      at(kAxial, kMinus, a, b) += (Nz[b] * N[a] / (2 * r) + Nz[b] * Nr[a] / 2) * rw;  // field −, test z
      at(kAxial, kAxial, a, b) += Nz[b] * Nz[a] * rw;
    }
}

void integrate_element(const TaylorHoodSpace& space, std::size_t e, double centroid_z, bool stress_form,
                       ElementQuadrature& eq, ElementMatrices& out) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  space.geometry().quadrature(e, eq);
  for (auto* v : {&out.m0, &out.k0, &out.k1, &out.k2}) v->assign(npe * npe, 0.0);
  out.t.assign(stress_form ? 9 * npe * npe : 0, 0.0);
  for (auto* v : {&out.bp, &out.bm, &out.bz}) v->assign(npp * npe, 0.0);
  out.fm.assign(npe, 0.0);
  out.gm.assign(npe, 0.0);
  out.fz.assign(npe, 0.0);
  const auto& P = space.pressure_basis();
  for (std::size_t q = 0; q < eq.w.size(); ++q) {
    const double r = eq.r[q], w = eq.w[q], zp = eq.z[q] - centroid_z;
    const double* N = &eq.N[q * npe];
    const double* Nr = &eq.dNr[q * npe];
    const double* Nz = &eq.dNz[q * npe];
    if (stress_form) add_stress_cross_term(npe, r, w, N, Nr, Nz, out.t);
    for (int a = 0; a < npe; ++a) {
      out.fm[a] += -zp * N[a] * r * w;
      out.gm[a] += -N[a] * r * w;
      out.fz[a] += r * N[a] * r * w;
      for (int b = 0; b < npe; ++b) {
        const double grad = (Nr[a] * Nr[b] + Nz[a] * Nz[b]) * r * w, mass = N[a] * N[b] * r * w;
        out.m0[a * npe + b] += mass;
        out.k0[a * npe + b] += grad;
        out.k1[a * npe + b] += grad + mass / (r * r);
        out.k2[a * npe + b] += grad + 4 * mass / (r * r);
      }
    }
    const double* Pq = &P[q * npp];
    for (int c = 0; c < npp; ++c)
      for (int b = 0; b < npe; ++b) {
        out.bp[c * npe + b] += Pq[c] * (0.5 * r * Nr[b] + N[b]) * w;
        out.bm[c * npe + b] += Pq[c] * 0.5 * r * Nr[b] * w;
        out.bz[c * npe + b] += Pq[c] * r * Nz[b] * w;
      }
  }
}

// Scatters one element into the real, imaginary and mass triplets of the complex pencil.
void scatter(const TaylorHoodSpace& space, std::size_t e, const ElementMatrices& em, double ekman, bool coriolis,
             Triplets& ar, Triplets& ai, Triplets& mass, std::vector<double>& f, std::vector<double>& g) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  const auto up = space.velocity(e, kPlus), um = space.velocity(e, kMinus), uz = space.velocity(e, kAxial);
  const auto p = space.pressure(e);
  for (int a = 0; a < npe; ++a) {
    if (um[a] >= 0) f[um[a]] += em.fm[a];
    if (um[a] >= 0) g[um[a]] += em.gm[a];
    if (uz[a] >= 0) f[uz[a]] += em.fz[a];
    for (int b = 0; b < npe; ++b) {
      const int ab = a * npe + b;
      mass.add(up[a], up[b], 0.5 * em.m0[ab]);
      mass.add(um[a], um[b], 0.5 * em.m0[ab]);
      mass.add(uz[a], uz[b], em.m0[ab]);
      if (coriolis) {
        ar.add(up[a], up[b], -em.m0[ab]);  // −C
        ar.add(um[a], um[b], em.m0[ab]);
      }
      ai.add(up[a], up[b], 0.5 * ekman * em.k2[ab]);
      ai.add(um[a], um[b], 0.5 * ekman * em.k0[ab]);
      ai.add(uz[a], uz[b], ekman * em.k1[ab]);
    }
  }
  if (!em.t.empty()) {
    const std::array<std::span<const int>, 3> dofs = {up, um, uz};
    for (int ci = 0; ci < 3; ++ci)
      for (int cj = 0; cj < 3; ++cj)
        for (int a = 0; a < npe; ++a)
          for (int b = 0; b < npe; ++b)
            ai.add(dofs[ci][a], dofs[cj][b], ekman * em.t[((ci * 3 + cj) * npe + a) * npe + b]);
  }
  for (int c = 0; c < npp; ++c)
    for (int b = 0; b < npe; ++b) {
      const int cb = c * npe + b;
      for (auto [cols, B] : {std::pair{up, &em.bp}, {um, &em.bm}, {uz, &em.bz}}) {
        ar.add(p[c], cols[b], (*B)[cb]);
        ar.add(cols[b], p[c], (*B)[cb]);
      }
    }
}

// The free surface r = b of a partially filled tank (header): one unknown η̃ = iη per velocity node of the surface off
// the walls (the contact line is pinned by no-slip: η = 0 there), numbered from `first`. Adds on this rank the
// surface's terms of Re A and 𝓜 and its coupling functional; returns the number of surface unknowns.
int add_free_surface(const TaylorHoodSpace& space, double centroid_z, int first, bool this_rank, Triplets& ar,
                     Triplets& mass, std::vector<double>& f, std::vector<double>& g) {
  const auto& mesh = space.geometry().mesh();
  if (mesh.free_edges.empty()) return 0;
  const int npe = mesh.nodes_per_element, nn = mesh.order + 1;
  std::vector<int> up(mesh.nodes.size(), -1), um(mesh.nodes.size(), -1), eta(mesh.nodes.size(), -1);
  for (std::size_t e = 0; e < space.num_elements(); ++e)
    for (int a = 0; a < npe; ++a) {
      const int node = mesh.triangles[e * npe + a];
      up[node] = space.velocity(e, kPlus)[a];
      um[node] = space.velocity(e, kMinus)[a];
    }
  int count = 0;
  for (int node : mesh.free_edges)
    if (up[node] >= 0 && eta[node] < 0) eta[node] = first + count++;
  f.resize(first + count, 0.0);
  g.resize(first + count, 0.0);
  if (!this_rank) return count;
  const double b = mesh.free_radius, b2 = b * b;
  const geometry::ReferenceEdge edge = geometry::reference_edge(mesh.order, 2 * mesh.order + 2);
  for (const FreeSurfacePoint& q : free_surface_points(mesh, edge)) {
    for (int a = 0; a < nn; ++a) {
      const int ea = eta[q.nodes[a]];
      if (ea < 0) continue;
      f[ea] += -b2 * (q.z - centroid_z) * q.N[a] * q.w;
      g[ea] += -b2 * q.N[a] * q.w;
      for (int c = 0; c < nn; ++c) {
        const double s = q.N[a] * q.N[c] * q.w;
        mass.add(ea, eta[q.nodes[c]], b2 * s);
        for (int u : {up[q.nodes[c]], um[q.nodes[c]]}) {  // V_r = (u+ + u−)/2
          ar.add(u, ea, 0.5 * b2 * s);
          ar.add(ea, u, 0.5 * b2 * s);
        }
      }
    }
  }
  return count;
}

}  // namespace

std::complex<double> block_bilinear(Vec x, Vec y) {
  MPI_Comm comm;
  petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(x), &comm), "PetscObjectGetComm");
  const PetscScalar* xs = nullptr;
  const PetscScalar* ys = nullptr;
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(x, &lo, &hi), "VecGetOwnershipRange");
  petsc_check(VecGetArrayRead(x, &xs), "VecGetArrayRead");
  petsc_check(VecGetArrayRead(y, &ys), "VecGetArrayRead");
  double local[2] = {0, 0}, total[2] = {0, 0};
  for (PetscInt j = 0; j + 1 < hi - lo; j += 2) {
    local[0] += xs[j] * ys[j] - xs[j + 1] * ys[j + 1];
    local[1] += xs[j] * ys[j + 1] + xs[j + 1] * ys[j];
  }
  petsc_check(VecRestoreArrayRead(x, &xs), "VecRestoreArrayRead");
  petsc_check(VecRestoreArrayRead(y, &ys), "VecRestoreArrayRead");
  MPI_Allreduce(local, total, 2, MPI_DOUBLE, MPI_SUM, comm);
  return {total[0], total[1]};
}

ViscousForms assemble_viscous_forms(const TaylorHoodSpace& space, double centroid_z, double ekman, MPI_Comm comm,
                                    bool coriolis) {
  if (!(ekman >= 0)) throw std::runtime_error("the Ekman number must be >= 0");
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::size_t ne = space.num_elements();
  const std::size_t first = ne * rank / ranks, last = ne * (rank + 1) / ranks;

  const bool free_surface = !space.geometry().mesh().free_edges.empty();
  Triplets ar, ai, mass;
  std::vector<double> f(space.size(), 0.0), g(space.size(), 0.0);
  const int n = space.size() + add_free_surface(space, centroid_z, space.size(), rank == 0, ar, mass, f, g);
  std::vector<double> f_all(n, 0.0), g_all(n, 0.0);
  ElementQuadrature eq;
  ElementMatrices em;
  for (std::size_t e = first; e < last; ++e) {
    integrate_element(space, e, centroid_z, free_surface, eq, em);
    scatter(space, e, em, ekman, coriolis, ar, ai, mass, f, g);
  }
  MPI_Allreduce(f.data(), f_all.data(), n, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(g.data(), g_all.data(), n, MPI_DOUBLE, MPI_SUM, comm);

  ViscousForms forms;
  forms.complex_size = n;
  forms.A = block_operator(comm, n, ar, ai, mass);
  forms.M = block_mass(comm, n, mass);
  forms.iM = block_imaginary_mass(comm, n, mass);
  forms.coupling = block_vector(forms.A, f_all);
  if (free_surface) forms.offset_coupling = block_vector(forms.A, g_all);
  forms.real_slots = block_vector(forms.A, std::vector<double>(n, 1.0));
  petsc_check(MatCreateVecs(forms.M, forms.mass_diagonal.out(), nullptr), "MatCreateVecs");
  petsc_check(MatGetDiagonal(forms.M, forms.mass_diagonal), "MatGetDiagonal");
  forms.complex_symmetric = true;  // the pencil of the header's comment (test ViscousFreeSurface.SymmetricFactorsSolveAsTheLu)
  return forms;
}

}  // namespace rc::modes
