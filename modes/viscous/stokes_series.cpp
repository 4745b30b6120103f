#include "stokes_series.hpp"

#include "mesh_broadcast.hpp"
#include "poincare_forms.hpp"
#include "shifted_solver.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_forms.hpp"

#include <mpi.h>

#include <numbers>
#include <stdexcept>

namespace rc::modes {

using cd = std::complex<double>;

cd StokesSeries::response(cd sigma, double ekman, int terms) const {
  const cd r[3] = {r0, r1_s * sigma + r1_0, (r2_ss * sigma + r2_s) * sigma + r2_0};
  cd sum = 0;
  double power = ekman;
  for (int n = 0; n < terms && n < 3; ++n, power *= ekman) sum += r[n] / power;
  return sum;
}

namespace {

PVec like(Vec v) {
  PVec out;
  petsc_check(VecDuplicate(v, out.out()), "VecDuplicate");
  return out;
}

// G b: the solver holds S(0) = −Â_S factored, so its solution is −G b.
PVec stokes_solve(ShiftedSolver& solver, Vec b) {
  PVec x = like(b);
  solver.solve(b, x);
  petsc_check(VecScale(x, -1.0), "VecScale");
  return x;
}

}  // namespace

StokesSeries stokes_series(const geometry::ShapeSpec& shape, const geometry::MeshOptions& mesh) {
  const TaylorHoodSpace space(mesh_on_root([&] { return geometry::mesh_meridian(shape, mesh); }, PETSC_COMM_WORLD));
  if (!space.geometry().mesh().free_edges.empty())
    throw std::runtime_error("the Stokes series is for a completely filled cavity (a free surface's normal stress "
                             "does not scale with Ek)");
  const double zc = integrate_fluid(space.geometry()).centroid_z;
  const ViscousForms stokes = assemble_viscous_forms(space, zc, 1.0, PETSC_COMM_WORLD, false);
  const ViscousForms full = assemble_viscous_forms(space, zc, 1.0, PETSC_COMM_WORLD, true);
  ShiftedSolver solver(stokes);
  solver.factor(0.0);
  const PVec x0 = stokes_solve(solver, stokes.coupling);
  // M x0, and C x0 = (A_S − A_C) x0 (A_C = A_S − C at the same Ek)
  PVec Mx = like(x0), Cx = like(x0), tmp = like(x0);
  petsc_check(MatMult(stokes.M, x0, Mx), "MatMult");
  petsc_check(MatMult(stokes.A, x0, Cx), "MatMult");
  petsc_check(MatMult(full.A, x0, tmp), "MatMult");
  petsc_check(VecAXPY(Cx, -1.0, tmp), "VecAXPY");
  const PVec zM = stokes_solve(solver, Mx), zC = stokes_solve(solver, Cx);
  const double pi = std::numbers::pi;
  StokesSeries s;
  s.r0 = -pi * block_bilinear(stokes.coupling, x0);
  s.r1_s = -pi * block_bilinear(x0, Mx);
  s.r1_0 = -pi * block_bilinear(x0, Cx);
  s.r2_ss = -pi * block_bilinear(Mx, zM);
  s.r2_s = -2.0 * pi * block_bilinear(Mx, zC);
  s.r2_0 = -pi * block_bilinear(Cx, zC);
  return s;
}

}  // namespace rc::modes
