// A complex pencil (A, 𝓜) assembled as triplets of real coefficients, written over PETSc's real scalars in the
// 2 × 2 block form of viscous_forms.hpp: unknown j of the complex problem is the pair (2j, 2j + 1) = (Re x_j, Im x_j),
//   Â = [[Ar, −Ai], [Ai, Ar]] pairwise,  M̂ = diag(𝓜, 𝓜) pairwise,  i𝓜 = [[0, −𝓜], [𝓜, 0]] pairwise,
// with whole pairs on each rank. Shared by the meridian forms (viscous_forms.cpp) and the 3-D ones
// (volume/viscous_volume_forms.cpp): any complex A, symmetric or not, and a real symmetric 𝓜.
#pragma once

#include "petsc_handles.hpp"

#include <mpi.h>

#include <complex>
#include <vector>

namespace rc::modes {

// Entries of one real coefficient matrix (Re A, Im A or 𝓜); a negative index (a constrained unknown) or a zero
// value is dropped.
struct Triplets {
  std::vector<PetscInt> i, j;
  std::vector<PetscScalar> v;
  void add(int row, int col, double value) {
    if (row < 0 || col < 0 || value == 0.0) return;
    i.push_back(row); j.push_back(col); v.push_back(value);
  }
};

// Â from the real and imaginary parts' triplets; it also holds explicit zeros wherever M̂ or i𝓜 has an entry (the
// diagonal included), so that every shifted matrix Â − Re τ M̂ − Im τ (i𝓜) is formed in place on Â's pattern
// (MatAXPY with a new pattern cost 0.6 s of 5.8 s on the Ek = 1e-6 sphere). n: the complex problem's unknowns.
PMat block_operator(MPI_Comm comm, int n, const Triplets& ar, const Triplets& ai, const Triplets& mass);

// M̂ (with an explicit zero diagonal: its pattern stays square where 𝓜 has an empty row, the pressure's).
PMat block_mass(MPI_Comm comm, int n, const Triplets& mass);

// The block of i𝓜 (complex shifts: σ𝓜 = Re σ M̂ + Im σ i𝓜).
PMat block_imaginary_mass(MPI_Comm comm, int n, const Triplets& mass);

// A block vector laid out like `like`'s columns holding real_part on the real slots and 0 on the imaginary ones.
PVec block_vector(Mat like, const std::vector<double>& real_part);
// ... holding a complex vector (its real and imaginary parts on the pairs' slots).
PVec block_vector(Mat like, const std::vector<std::complex<double>>& values);

}  // namespace rc::modes
