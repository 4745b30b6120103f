// The exact nonzero count of each row of a matrix assembled over a finite-element space's elements (any space with
// ndof(), num_elements() and element_dofs(e), a dof of −1 being constrained), so that assembly never reallocates.
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <vector>

namespace rc::modes {

template <class Space>
std::vector<PetscInt> row_nonzeros(const Space& space) {
  std::vector<std::vector<int>> cols(space.ndof());
  for (std::size_t e = 0; e < space.num_elements(); ++e) {
    const auto dofs = space.element_dofs(e);
    for (int i : dofs)
      if (i >= 0)
        for (int j : dofs)
          if (j >= 0) cols[i].push_back(j);
  }
  std::vector<PetscInt> nnz(space.ndof());
  for (int i = 0; i < space.ndof(); ++i) {
    std::sort(cols[i].begin(), cols[i].end());
    nnz[i] = std::unique(cols[i].begin(), cols[i].end()) - cols[i].begin();
  }
  return nnz;
}

}  // namespace rc::modes
