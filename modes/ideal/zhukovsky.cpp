#include "zhukovsky.hpp"

#include <numbers>

namespace rc::modes {

ZhukovskyResult zhukovsky_inertia(const PoincareForms& forms, const StiffnessSolver& solver) {
  PVec chi, res;
  petsc_check(VecDuplicate(forms.zhukovsky_rhs, chi.out()), "VecDuplicate");
  petsc_check(VecDuplicate(forms.zhukovsky_rhs, res.out()), "VecDuplicate");
  solver.solve(forms.zhukovsky_rhs, chi);
  PetscScalar bx = 0;
  PetscReal nb = 0, nr = 0;
  petsc_check(VecDot(forms.zhukovsky_rhs, chi, &bx), "VecDot");
  petsc_check(MatMult(forms.M, chi, res), "MatMult");
  petsc_check(VecAXPY(res, -1.0, forms.zhukovsky_rhs), "VecAXPY");
  petsc_check(VecNorm(res, NORM_2, &nr), "VecNorm");
  petsc_check(VecNorm(forms.zhukovsky_rhs, NORM_2, &nb), "VecNorm");
  ZhukovskyResult z;
  z.J_zh = std::numbers::pi * bx;
  z.relative_residual = nb > 0 ? nr / nb : 0.0;
  return z;
}

}  // namespace rc::modes
