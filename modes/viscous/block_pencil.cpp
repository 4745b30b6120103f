#include "block_pencil.hpp"

#include "triplet_matrix.hpp"

namespace rc::modes {
namespace {

PMat create_block_matrix(MPI_Comm comm, int complex_size, std::vector<PetscInt>& i, std::vector<PetscInt>& j,
                         const std::vector<PetscScalar>& v) {
  // Whole (Re, Im) pairs per rank, so that a complex unknown never straddles two ranks.
  PetscInt local = PETSC_DECIDE, global = complex_size;
  petsc_check(PetscSplitOwnership(comm, &local, &global), "PetscSplitOwnership");
  return triplet_matrix(comm, 2 * local, 2 * global, i, j, v);
}

}  // namespace

PMat block_operator(MPI_Comm comm, int n, const Triplets& ar, const Triplets& ai, const Triplets& mass) {
  std::vector<PetscInt> I, J;
  std::vector<PetscScalar> V;
  const std::size_t count = 2 * ar.v.size() + 2 * ai.v.size() + 4 * mass.v.size() + 2 * n;
  I.reserve(count); J.reserve(count); V.reserve(count);
  auto put = [&](PetscInt r, PetscInt c, double x) { I.push_back(r); J.push_back(c); V.push_back(x); };
  for (std::size_t k = 0; k < mass.v.size(); ++k)
    for (int a : {0, 1})
      for (int b : {0, 1}) put(2 * mass.i[k] + a, 2 * mass.j[k] + b, 0.0);
  for (PetscInt d = 0; d < 2 * n; ++d) put(d, d, 0.0);
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
  return block_vector(like, std::vector<std::complex<double>>(real_part.begin(), real_part.end()));
}

PVec block_vector(Mat like, const std::vector<std::complex<double>>& values) {
  PVec v;
  petsc_check(MatCreateVecs(like, v.out(), nullptr), "MatCreateVecs");
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(v, &lo, &hi), "VecGetOwnershipRange");
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(v, &a), "VecGetArray");
  for (PetscInt g = lo; g < hi; ++g) a[g - lo] = g % 2 == 0 ? values[g / 2].real() : values[g / 2].imag();
  petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
  return v;
}

}  // namespace rc::modes
