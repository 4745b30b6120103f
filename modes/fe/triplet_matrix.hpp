// A PETSc matrix from (row, column, value) triplets whose repeats add up, as element-by-element assembly makes them.
// PETSc's own COO assembly sorts every triplet (1.8 s of 8.5 s on the Ek = 1e-5 sphere's 161 000 unknowns, order 6);
// here the triplets are bucketed by row and sorted within each short row first, so a serial run hands PETSc its CSR
// directly and a parallel one hands its COO assembly each entry once.
#pragma once

#include "petsc_handles.hpp"

#include <vector>

namespace rc::modes {

// The global_rows × global_rows matrix of type MATAIJ with local_rows rows on this rank (PETSc's split when
// PETSC_DECIDE), holding the sum of this rank's triplets and every other rank's (a triplet may name any row).
PMat triplet_matrix(MPI_Comm comm, PetscInt local_rows, PetscInt global_rows, const std::vector<PetscInt>& rows,
                    const std::vector<PetscInt>& cols, const std::vector<PetscScalar>& values);

}  // namespace rc::modes
