#include "poincare_forms.hpp"

#include "sparsity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rc::modes {
namespace {


PMat create_matrix(int n, const std::vector<PetscInt>& nnz) {
  PMat A;
  petsc_check(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), A.out()), "MatCreateSeqAIJ");
  petsc_check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  return A;
}

PVec create_vector(int n) {
  PVec v;
  petsc_check(VecCreateSeq(PETSC_COMM_SELF, n, v.out()), "VecCreateSeq");
  return v;
}

void finish(Mat A) {
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

void copy_into(Vec v, const std::vector<double>& values) {
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  std::copy(values.begin(), values.end(), a);
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
}

}  // namespace

FluidIntegrals integrate_fluid(const FESpace& space) {
  ElementQuadrature eq;
  double v = 0, vz = 0, vzz = 0, vrr = 0;  // ∫∫ r, ∫∫ z r, ∫∫ z² r, ∫∫ r³ (dr dz)
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double r = eq.r[q], z = eq.z[q], w = eq.w[q] * r;
      v += w; vz += w * z; vzz += w * z * z; vrr += w * r * r;
    }
  }
  return fluid_from_moments(v, vz, vzz, vrr);
}

FluidIntegrals fluid_from_moments(double r1, double zr, double zzr, double r3) {
  FluidIntegrals f;
  f.volume = 2 * std::numbers::pi * r1;
  f.centroid_z = zr / r1;
  const double zz_about_centroid = zzr - r1 * f.centroid_z * f.centroid_z;
  f.A_f = std::numbers::pi * (r3 + 2 * zz_about_centroid);
  f.C_f = 2 * std::numbers::pi * r3;
  return f;
}

PoincareForms assemble_poincare_forms(const FESpace& space, double centroid_z) {
  const int n = space.ndof();
  const int npe = space.nodes_per_element();
  const auto nnz = row_nonzeros(space);
  PoincareForms F;
  F.Kh = create_matrix(n, nnz);
  F.Kz = create_matrix(n, nnz);
  F.Gc = create_matrix(n, nnz);
  F.f1 = create_vector(n);
  F.f2 = create_vector(n);

  ElementQuadrature eq;
  std::vector<double> kh(npe * npe), kz(npe * npe), gc(npe * npe), f1(npe), f2(npe);
  std::vector<PetscInt> idx(npe);
  std::vector<double> f1_all(n, 0.0), f2_all(n, 0.0);
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    std::fill(kh.begin(), kh.end(), 0.0); std::fill(kz.begin(), kz.end(), 0.0);
    std::fill(gc.begin(), gc.end(), 0.0); std::fill(f1.begin(), f1.end(), 0.0);
    std::fill(f2.begin(), f2.end(), 0.0);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double r = eq.r[q], zp = eq.z[q] - centroid_z, w = eq.w[q];
      const double* N = &eq.N[q * npe];
      const double* Nr = &eq.dNr[q * npe];
      const double* Nz = &eq.dNz[q * npe];
      for (int i = 0; i < npe; ++i) {
        f1[i] += zp * (r * Nr[i] + N[i]) * w;   // z' (r q)_r
        f2[i] += r * r * Nz[i] * w;             // r² q_z
        for (int j = 0; j < npe; ++j) {
          kh[i * npe + j] += (Nr[i] * Nr[j] + N[i] * N[j] / (r * r)) * r * w;
          kz[i * npe + j] += Nz[i] * Nz[j] * r * w;
          gc[i * npe + j] += (Nr[i] * N[j] + N[i] * Nr[j]) * w;
        }
      }
    }
    auto dofs = space.element_dofs(e);
    for (int a = 0; a < npe; ++a) idx[a] = dofs[a];  // -1 (axis) entries are ignored by PETSc
    petsc_check(MatSetValues(F.Kh, npe, idx.data(), npe, idx.data(), kh.data(), ADD_VALUES), "MatSetValues");
    petsc_check(MatSetValues(F.Kz, npe, idx.data(), npe, idx.data(), kz.data(), ADD_VALUES), "MatSetValues");
    petsc_check(MatSetValues(F.Gc, npe, idx.data(), npe, idx.data(), gc.data(), ADD_VALUES), "MatSetValues");
    for (int a = 0; a < npe; ++a) {
      if (idx[a] < 0) continue;  // VecSetValues does not skip negative indices in optimised PETSc builds
      f1_all[idx[a]] += f1[a];
      f2_all[idx[a]] += f2[a];
    }
  }
  for (Mat A : {F.Kh.get(), F.Kz.get(), F.Gc.get()}) finish(A);
  copy_into(F.f1, f1_all);
  copy_into(F.f2, f2_all);
  petsc_check(MatDuplicate(F.Kh, MAT_COPY_VALUES, F.M.out()), "MatDuplicate");
  petsc_check(MatAXPY(F.M, 1.0, F.Kz, SAME_NONZERO_PATTERN), "MatAXPY");
  petsc_check(VecDuplicate(F.f1, F.zhukovsky_rhs.out()), "VecDuplicate");
  petsc_check(VecWAXPY(F.zhukovsky_rhs, -1.0, F.f2, F.f1), "VecWAXPY");
  return F;
}

}  // namespace rc::modes
