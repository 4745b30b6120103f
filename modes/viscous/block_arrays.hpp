// A block vector's local pairs (Re, Im) read as the complex numbers they hold, and written back (viscous_forms.hpp's
// layout: complex unknown j in slots 2j, 2j + 1; a pair never straddles two ranks). The Krylov response reductions
// (krylov_response.*, viscous_volume_krylov.*) keep their bases as such local rows.
//
// A block of such columns is, in memory, the real dense matrix of the block vectors side by side (Eigen's column-major
// complex storage interleaves Re and Im exactly as the block layout does), so a sparse block matrix is applied to all
// of them at once through PETSc's sparse × dense product: one pass over the matrix for every four columns instead of
// one per column — the basis's products with 𝓜 and 𝒜 took 2.1 s of a P6 Krylov point's 7.5 s, 1.0 s so
// (docs/benchmarks.md, "Krylov point").
#pragma once

#include "petsc_handles.hpp"

#include <Eigen/Core>

#include <complex>

namespace rc::modes {

inline Eigen::VectorXcd local_pairs(Vec v) {
  PetscInt n = 0;
  const PetscScalar* a = nullptr;
  petsc_check(VecGetLocalSize(v, &n), "VecGetLocalSize");
  petsc_check(VecGetArrayRead(v, &a), "VecGetArrayRead");
  Eigen::VectorXcd out = Eigen::Map<const Eigen::VectorXcd>(reinterpret_cast<const std::complex<double>*>(a), n / 2);
  petsc_check(VecRestoreArrayRead(v, &a), "VecRestoreArrayRead");
  return out;
}

inline void store_pairs(const Eigen::VectorXcd& x, Vec v) {
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  Eigen::Map<Eigen::VectorXcd>(reinterpret_cast<std::complex<double>*>(a), x.size()) = x;
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
}

// op · W for the block matrix op and the complex columns W (this rank's local rows).
Eigen::MatrixXcd block_product(Mat op, const Eigen::MatrixXcd& W);

}  // namespace rc::modes
