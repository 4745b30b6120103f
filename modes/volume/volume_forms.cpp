#include "volume_forms.hpp"

#include "sparsity.hpp"

#include <algorithm>
#include <vector>

namespace rc::modes {
namespace {

PMat create_matrix(int n, const std::vector<PetscInt>& nnz) {
  PMat A;
  petsc_check(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), A.out()), "MatCreateSeqAIJ");
  return A;
}

void finish(Mat A) {
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

// [A 0; 0 A] (off = false) or [0 −A; A 0] (off = true) from an n × n matrix.
PMat two_by_two(Mat A, bool off) {
  PetscInt n = 0;
  petsc_check(MatGetSize(A, &n, nullptr), "MatGetSize");
  std::vector<PetscInt> nnz(2 * n);
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt nc = 0;
    petsc_check(MatGetRow(A, i, &nc, nullptr, nullptr), "MatGetRow");
    nnz[i] = nnz[n + i] = nc;
    petsc_check(MatRestoreRow(A, i, &nc, nullptr, nullptr), "MatRestoreRow");
  }
  PMat B = create_matrix(2 * n, nnz);
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt nc = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    petsc_check(MatGetRow(A, i, &nc, &cols, &vals), "MatGetRow");
    std::vector<PetscInt> shifted(cols, cols + nc);
    std::vector<PetscScalar> negated(vals, vals + nc);
    for (auto& c : shifted) c += n;
    for (auto& v : negated) v = -v;
    const PetscInt lower = n + i;
    if (off) {
      petsc_check(MatSetValues(B, 1, &i, nc, shifted.data(), negated.data(), INSERT_VALUES), "MatSetValues");
      petsc_check(MatSetValues(B, 1, &lower, nc, cols, vals, INSERT_VALUES), "MatSetValues");
    } else {
      petsc_check(MatSetValues(B, 1, &i, nc, cols, vals, INSERT_VALUES), "MatSetValues");
      petsc_check(MatSetValues(B, 1, &lower, nc, shifted.data(), vals, INSERT_VALUES), "MatSetValues");
    }
    petsc_check(MatRestoreRow(A, i, &nc, &cols, &vals), "MatRestoreRow");
  }
  finish(B);
  petsc_check(MatSetOption(B, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  return B;
}

}  // namespace

VolumeIntegrals integrate_volume(const VolumeSpace& space) {
  VolumeQuadrature eq;
  double v = 0, s[3] = {0, 0, 0}, ss[3][3] = {};
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double x[3] = {eq.x[q], eq.y[q], eq.z[q]}, w = eq.w[q];
      v += w;
      for (int j = 0; j < 3; ++j) {
        s[j] += w * x[j];
        for (int k = 0; k < 3; ++k) ss[j][k] += w * x[j] * x[k];
      }
    }
  }
  VolumeIntegrals f;
  f.volume = v;
  for (int j = 0; j < 3; ++j) f.centroid[j] = s[j] / v;
  double second[3][3];  // ∫ r_j r_k about the centroid
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) second[j][k] = ss[j][k] - v * f.centroid[j] * f.centroid[k];
  const double trace = second[0][0] + second[1][1] + second[2][2];
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) f.inertia[j][k] = (j == k ? trace : 0.0) - second[j][k];
  return f;
}

VolumeForms assemble_volume_forms(const VolumeSpace& space) {
  const int n = space.ndof(), npe = space.nodes_per_element();
  const auto nnz = row_nonzeros(space);
  VolumeForms F;
  F.M = create_matrix(n, nnz);
  F.Kz = create_matrix(n, nnz);
  F.G = create_matrix(n, nnz);
  VolumeQuadrature eq;
  std::vector<double> m(npe * npe), kz(npe * npe), g(npe * npe);
  std::vector<PetscInt> idx(npe);
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    space.quadrature(e, eq);
    std::fill(m.begin(), m.end(), 0.0); std::fill(kz.begin(), kz.end(), 0.0); std::fill(g.begin(), g.end(), 0.0);
    for (std::size_t q = 0; q < eq.w.size(); ++q) {
      const double w = eq.w[q];
      const double *X = &eq.dNx[q * npe], *Y = &eq.dNy[q * npe], *Z = &eq.dNz[q * npe];
      for (int i = 0; i < npe; ++i)
        for (int j = 0; j < npe; ++j) {
          m[i * npe + j] += (X[i] * X[j] + Y[i] * Y[j] + Z[i] * Z[j]) * w;
          kz[i * npe + j] += Z[i] * Z[j] * w;
          g[i * npe + j] += (Y[i] * X[j] - X[i] * Y[j]) * w;  // q_y p_x − q_x p_y
        }
    }
    const auto dofs = space.element_dofs(e);
    for (int a = 0; a < npe; ++a) idx[a] = dofs[a];  // the pinned node (-1) is ignored by PETSc
    petsc_check(MatSetValues(F.M, npe, idx.data(), npe, idx.data(), m.data(), ADD_VALUES), "MatSetValues");
    petsc_check(MatSetValues(F.Kz, npe, idx.data(), npe, idx.data(), kz.data(), ADD_VALUES), "MatSetValues");
    petsc_check(MatSetValues(F.G, npe, idx.data(), npe, idx.data(), g.data(), ADD_VALUES), "MatSetValues");
  }
  for (Mat A : {F.M.get(), F.Kz.get(), F.G.get()}) finish(A);
  petsc_check(MatSetOption(F.M, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  petsc_check(MatSetOption(F.M, MAT_SPD, PETSC_TRUE), "MatSetOption");
  return F;
}

PoincareForms real_form_pencil(const VolumeForms& forms) {
  PoincareForms P;
  P.M = two_by_two(forms.M, false);
  P.Kz = two_by_two(forms.Kz, false);
  P.Gc = two_by_two(forms.G, true);
  petsc_check(MatDuplicate(P.M, MAT_COPY_VALUES, P.Kh.out()), "MatDuplicate");
  petsc_check(MatAXPY(P.Kh, -1.0, P.Kz, SAME_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatCreateVecs(P.M, P.f1.out(), nullptr), "MatCreateVecs");
  petsc_check(VecSet(P.f1, 0.0), "VecSet");
  petsc_check(VecDuplicate(P.f1, P.f2.out()), "VecDuplicate");
  petsc_check(VecSet(P.f2, 0.0), "VecSet");
  petsc_check(VecDuplicate(P.f1, P.zhukovsky_rhs.out()), "VecDuplicate");
  petsc_check(VecSet(P.zhukovsky_rhs, 0.0), "VecSet");
  return P;
}

}  // namespace rc::modes
