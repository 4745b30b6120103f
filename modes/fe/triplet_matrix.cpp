#include "triplet_matrix.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rc::modes {
namespace {

// Compressed rows: repeats summed, columns ascending within each row.
struct CompressedRows {
  std::vector<PetscInt> start, cols;
  std::vector<PetscScalar> values;
};

CompressedRows compress(PetscInt n, const std::vector<PetscInt>& rows, const std::vector<PetscInt>& cols,
                        const std::vector<PetscScalar>& values) {
  std::vector<PetscInt> start(n + 1, 0);
  for (PetscInt r : rows) {
    if (r < 0 || r >= n) throw std::out_of_range("triplet_matrix: a row outside the matrix");
    ++start[r + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<PetscInt, PetscScalar>> bucket(rows.size());
  std::vector<PetscInt> next(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < rows.size(); ++k) bucket[next[rows[k]]++] = {cols[k], values[k]};
  CompressedRows out;
  out.start.assign(n + 1, 0);
  out.cols.reserve(rows.size());
  out.values.reserve(rows.size());
  for (PetscInt r = 0; r < n; ++r) {
    const auto first = bucket.begin() + start[r], last = bucket.begin() + start[r + 1];
    std::sort(first, last, [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto it = first; it != last; ++it) {
      if (it != first && it->first == std::prev(it)->first) { out.values.back() += it->second; continue; }
      out.cols.push_back(it->first);
      out.values.push_back(it->second);
    }
    out.start[r + 1] = static_cast<PetscInt>(out.cols.size());
  }
  return out;
}

}  // namespace

PMat triplet_matrix(MPI_Comm comm, PetscInt local_rows, PetscInt global_rows, const std::vector<PetscInt>& rows,
                    const std::vector<PetscInt>& cols, const std::vector<PetscScalar>& values) {
  if (rows.size() != cols.size() || rows.size() != values.size())
    throw std::invalid_argument("triplet_matrix: rows, columns and values differ in length");
  PMat A;
  petsc_check(MatCreate(comm, A.out()), "MatCreate");
  petsc_check(MatSetSizes(A, local_rows, local_rows, global_rows, global_rows), "MatSetSizes");
  petsc_check(MatSetType(A, MATAIJ), "MatSetType");
  const CompressedRows c = compress(global_rows, rows, cols, values);
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  if (ranks == 1) {
    petsc_check(MatSeqAIJSetPreallocationCSR(A, c.start.data(), c.cols.data(), c.values.data()),
                "MatSeqAIJSetPreallocationCSR");
    return A;
  }
  std::vector<PetscInt> i(c.cols.size());
  for (PetscInt r = 0; r < global_rows; ++r) std::fill(i.begin() + c.start[r], i.begin() + c.start[r + 1], r);
  std::vector<PetscInt> j = c.cols;  // PETSc's COO preallocation may reorder its index arrays
  petsc_check(MatSetPreallocationCOO(A, static_cast<PetscCount>(i.size()), i.data(), j.data()), "MatSetPreallocationCOO");
  petsc_check(MatSetValuesCOO(A, c.values.data(), ADD_VALUES), "MatSetValuesCOO");
  return A;
}

}  // namespace rc::modes
