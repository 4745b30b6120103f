#include "block_arrays.hpp"

#include <algorithm>

namespace rc::modes {

Eigen::MatrixXcd block_product(Mat op, const Eigen::MatrixXcd& W) {
  Eigen::MatrixXcd out(W.rows(), W.cols());
  if (W.cols() == 0) return out;
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(op));
  const auto local_rows = static_cast<PetscInt>(2 * W.rows()), columns = static_cast<PetscInt>(W.cols());
  // PETSc reads W's storage in place: the product never writes its right factor.
  auto* data = const_cast<PetscScalar*>(reinterpret_cast<const PetscScalar*>(W.data()));
  PMat right, product;
  petsc_check(MatCreateDense(comm, local_rows, PETSC_DECIDE, PETSC_DETERMINE, columns, data, right.out()),
              "MatCreateDense");
  petsc_check(MatMatMult(op, right, MAT_INITIAL_MATRIX, PETSC_DEFAULT, product.out()), "MatMatMult");
  const PetscScalar* result = nullptr;
  PetscInt lda = 0;
  petsc_check(MatDenseGetLDA(product, &lda), "MatDenseGetLDA");
  petsc_check(MatDenseGetArrayRead(product, &result), "MatDenseGetArrayRead");
  auto* target = reinterpret_cast<PetscScalar*>(out.data());
  for (PetscInt j = 0; j < columns; ++j) std::copy_n(result + j * lda, local_rows, target + j * local_rows);
  petsc_check(MatDenseRestoreArrayRead(product, &result), "MatDenseRestoreArrayRead");
  return out;
}

}  // namespace rc::modes
