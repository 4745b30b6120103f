#include "viscous_forms.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace rc::modes {
namespace {

// Entries of the complex pencil, each a real coefficient of Re A (ar), Im A (ai) or 𝓜 (m).
struct Triplets {
  std::vector<PetscInt> i, j;
  std::vector<PetscScalar> v;
  void add(int row, int col, double value) {
    if (row < 0 || col < 0 || value == 0.0) return;
    i.push_back(row); j.push_back(col); v.push_back(value);
  }
};

struct ElementMatrices {
  // Per pair of local velocity nodes: M0, K0, K1, K2; per (pressure node, velocity node): the three B rows.
  std::vector<double> m0, k0, k1, k2, bp, bm, bz;
  std::vector<double> fm, fz;  // coupling functional on u− and u_z
};

void integrate_element(const TaylorHoodSpace& space, std::size_t e, double centroid_z, ElementQuadrature& eq,
                       ElementMatrices& out) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  space.geometry().quadrature(e, eq);
  for (auto* v : {&out.m0, &out.k0, &out.k1, &out.k2}) v->assign(npe * npe, 0.0);
  for (auto* v : {&out.bp, &out.bm, &out.bz}) v->assign(npp * npe, 0.0);
  out.fm.assign(npe, 0.0);
  out.fz.assign(npe, 0.0);
  const auto& P = space.pressure_basis();
  for (std::size_t q = 0; q < eq.w.size(); ++q) {
    const double r = eq.r[q], w = eq.w[q], zp = eq.z[q] - centroid_z;
    const double* N = &eq.N[q * npe];
    const double* Nr = &eq.dNr[q * npe];
    const double* Nz = &eq.dNz[q * npe];
    for (int a = 0; a < npe; ++a) {
      out.fm[a] += -zp * N[a] * r * w;
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
void scatter(const TaylorHoodSpace& space, std::size_t e, const ElementMatrices& em, double ekman, Triplets& ar,
             Triplets& ai, Triplets& mass, std::vector<double>& f) {
  const int npe = space.velocity_nodes_per_element(), npp = space.pressure_nodes_per_element();
  const auto up = space.velocity(e, kPlus), um = space.velocity(e, kMinus), uz = space.velocity(e, kAxial);
  const auto p = space.pressure(e);
  for (int a = 0; a < npe; ++a) {
    if (um[a] >= 0) f[um[a]] += em.fm[a];
    if (uz[a] >= 0) f[uz[a]] += em.fz[a];
    for (int b = 0; b < npe; ++b) {
      const int ab = a * npe + b;
      mass.add(up[a], up[b], 0.5 * em.m0[ab]);
      mass.add(um[a], um[b], 0.5 * em.m0[ab]);
      mass.add(uz[a], uz[b], em.m0[ab]);
      ar.add(up[a], up[b], -em.m0[ab]);  // −C
      ar.add(um[a], um[b], em.m0[ab]);
      ai.add(up[a], up[b], 0.5 * ekman * em.k2[ab]);
      ai.add(um[a], um[b], 0.5 * ekman * em.k0[ab]);
      ai.add(uz[a], uz[b], ekman * em.k1[ab]);
    }
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

PMat create_block_matrix(MPI_Comm comm, int complex_size, std::vector<PetscInt>& i, std::vector<PetscInt>& j,
                         const std::vector<PetscScalar>& v) {
  PMat A;
  petsc_check(MatCreate(comm, A.out()), "MatCreate");
  // Whole (Re, Im) pairs per rank, so that a complex unknown never straddles two ranks.
  PetscInt local = PETSC_DECIDE, global = complex_size;
  petsc_check(PetscSplitOwnership(comm, &local, &global), "PetscSplitOwnership");
  petsc_check(MatSetSizes(A, 2 * local, 2 * local, 2 * global, 2 * global), "MatSetSizes");
  petsc_check(MatSetType(A, MATAIJ), "MatSetType");
  petsc_check(MatSetPreallocationCOO(A, static_cast<PetscCount>(i.size()), i.data(), j.data()),
              "MatSetPreallocationCOO");
  petsc_check(MatSetValuesCOO(A, v.data(), ADD_VALUES), "MatSetValuesCOO");
  return A;
}

// Â from the complex pencil's real and imaginary triplets (see the header), M̂ from 𝓜's.
PMat block_operator(MPI_Comm comm, int n, const Triplets& ar, const Triplets& ai) {
  std::vector<PetscInt> I, J;
  std::vector<PetscScalar> V;
  const std::size_t count = 2 * ar.v.size() + 2 * ai.v.size();
  I.reserve(count); J.reserve(count); V.reserve(count);
  auto put = [&](PetscInt r, PetscInt c, double x) { I.push_back(r); J.push_back(c); V.push_back(x); };
  for (std::size_t k = 0; k < ar.v.size(); ++k) {
    put(2 * ar.i[k], 2 * ar.j[k], ar.v[k]);
    put(2 * ar.i[k] + 1, 2 * ar.j[k] + 1, ar.v[k]);
  }
  for (std::size_t k = 0; k < ai.v.size(); ++k) {
    put(2 * ai.i[k], 2 * ai.j[k] + 1, -ai.v[k]);
    put(2 * ai.i[k] + 1, 2 * ai.j[k], ai.v[k]);
  }
  return create_block_matrix(comm, n, I, J, V);
}

PMat block_mass(MPI_Comm comm, int n, const Triplets& m) {
  // The pressure block of 𝓜 is zero; an explicit zero diagonal keeps M̂'s pattern square for MatAXPY.
  std::vector<PetscInt> I, J;
  std::vector<PetscScalar> V;
  for (std::size_t k = 0; k < m.v.size(); ++k)
    for (int part : {0, 1}) { I.push_back(2 * m.i[k] + part); J.push_back(2 * m.j[k] + part); V.push_back(m.v[k]); }
  for (int d = 0; d < 2 * n; ++d) { I.push_back(d); J.push_back(d); V.push_back(0.0); }
  return create_block_matrix(comm, n, I, J, V);
}

PMat block_imaginary_mass(MPI_Comm comm, int n, const Triplets& m) {
  std::vector<PetscInt> I, J;
  std::vector<PetscScalar> V;
  for (std::size_t k = 0; k < m.v.size(); ++k) {
    I.push_back(2 * m.i[k]); J.push_back(2 * m.j[k] + 1); V.push_back(-m.v[k]);
    I.push_back(2 * m.i[k] + 1); J.push_back(2 * m.j[k]); V.push_back(m.v[k]);
  }
  for (int d = 0; d < 2 * n; ++d) { I.push_back(d); J.push_back(d); V.push_back(0.0); }
  return create_block_matrix(comm, n, I, J, V);
}

PVec block_vector(Mat like, const std::vector<double>& real_part) {
  PVec v;
  petsc_check(MatCreateVecs(like, v.out(), nullptr), "MatCreateVecs");
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(v, &lo, &hi), "VecGetOwnershipRange");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  for (PetscInt g = lo; g < hi; ++g) a[g - lo] = g % 2 == 0 ? real_part[g / 2] : 0.0;
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
  return v;
}

}  // namespace

ViscousForms assemble_viscous_forms(const TaylorHoodSpace& space, double centroid_z, double ekman, MPI_Comm comm) {
  if (!(ekman >= 0)) throw std::runtime_error("the Ekman number must be >= 0");
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::size_t ne = space.num_elements();
  const std::size_t first = ne * rank / ranks, last = ne * (rank + 1) / ranks;

  const int n = space.size();
  Triplets ar, ai, mass;
  std::vector<double> f(n, 0.0), f_all(n, 0.0);
  ElementQuadrature eq;
  ElementMatrices em;
  for (std::size_t e = first; e < last; ++e) {
    integrate_element(space, e, centroid_z, eq, em);
    scatter(space, e, em, ekman, ar, ai, mass, f);
  }
  MPI_Allreduce(f.data(), f_all.data(), n, MPI_DOUBLE, MPI_SUM, comm);

  ViscousForms forms;
  forms.complex_size = n;
  forms.A = block_operator(comm, n, ar, ai);
  forms.M = block_mass(comm, n, mass);
  forms.iM = block_imaginary_mass(comm, n, mass);
  forms.coupling = block_vector(forms.A, f_all);
  forms.real_slots = block_vector(forms.A, std::vector<double>(n, 1.0));
  petsc_check(MatCreateVecs(forms.M, forms.mass_diagonal.out(), nullptr), "MatCreateVecs");
  petsc_check(MatGetDiagonal(forms.M, forms.mass_diagonal), "MatGetDiagonal");
  return forms;
}

}  // namespace rc::modes
