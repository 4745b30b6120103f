#include "volume_forms.hpp"

#include "triplet_matrix.hpp"

#include <algorithm>
#include <vector>

namespace rc::modes {
namespace {

// Element-matrix entries gathered for one matrix (the pinned node, index −1, left out).
struct Entries {
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  void add(PetscInt i, PetscInt j, double v) {
    if (i < 0 || j < 0) return;
    rows.push_back(i); cols.push_back(j); values.push_back(v);
  }
};

PMat matrix_of(MPI_Comm comm, PetscInt n, const Entries& e) {
  PetscInt local = PETSC_DECIDE, global = n;
  petsc_check(PetscSplitOwnership(comm, &local, &global), "PetscSplitOwnership");
  return triplet_matrix(comm, local, n, e.rows, e.cols, e.values);
}

// [A 0; 0 A] (off = false) or [0 −A; A 0] (off = true) from an n × n matrix, each rank handing in its rows of A.
PMat two_by_two(Mat A, bool off) {
  PetscInt n = 0, lo = 0, hi = 0;
  petsc_check(MatGetSize(A, &n, nullptr), "MatGetSize");
  petsc_check(MatGetOwnershipRange(A, &lo, &hi), "MatGetOwnershipRange");
  Entries e;
  for (PetscInt i = lo; i < hi; ++i) {
    PetscInt nc = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    petsc_check(MatGetRow(A, i, &nc, &cols, &vals), "MatGetRow");
    for (PetscInt k = 0; k < nc; ++k) {
      if (off) {
        e.add(i, n + cols[k], -vals[k]);
        e.add(n + i, cols[k], vals[k]);
      } else {
        e.add(i, cols[k], vals[k]);
        e.add(n + i, n + cols[k], vals[k]);
      }
    }
    petsc_check(MatRestoreRow(A, i, &nc, &cols, &vals), "MatRestoreRow");
  }
  PMat B = matrix_of(PetscObjectComm(reinterpret_cast<PetscObject>(A)), 2 * n, e);
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

ElementRange rank_elements(const VolumeSpace& space, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const std::size_t n = space.num_elements(), r = static_cast<std::size_t>(rank), p = static_cast<std::size_t>(ranks);
  return {n * r / p, n * (r + 1) / p};
}

VolumeForms assemble_volume_forms(const VolumeSpace& space, MPI_Comm comm) {
  const int n = space.ndof(), npe = space.nodes_per_element();
  Entries em, ekz, eg;
  VolumeQuadrature eq;
  std::vector<double> m(npe * npe), kz(npe * npe), g(npe * npe);
  const ElementRange mine = rank_elements(space, comm);
  for (std::size_t e = mine.begin; e < mine.end; ++e) {
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
    const auto dofs = space.element_dofs(e);  // the pinned node (−1) is left out
    for (int a = 0; a < npe; ++a)
      for (int b = 0; b < npe; ++b) {
        em.add(dofs[a], dofs[b], m[a * npe + b]);
        ekz.add(dofs[a], dofs[b], kz[a * npe + b]);
        eg.add(dofs[a], dofs[b], g[a * npe + b]);
      }
  }
  VolumeForms F;
  F.M = matrix_of(comm, n, em);
  F.Kz = matrix_of(comm, n, ekz);
  F.G = matrix_of(comm, n, eg);
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

PMat shifted_real_pencil(const PoincareForms& real, double sigma) {
  PMat Q;
  petsc_check(MatDuplicate(real.M, MAT_COPY_VALUES, Q.out()), "MatDuplicate");
  petsc_check(MatScale(Q, sigma * sigma), "MatScale");
  petsc_check(MatAXPY(Q, -4.0, real.Kz, SUBSET_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatAXPY(Q, 2 * sigma, real.Gc, DIFFERENT_NONZERO_PATTERN), "MatAXPY");
  petsc_check(MatSetOption(Q, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  return Q;
}

}  // namespace rc::modes
