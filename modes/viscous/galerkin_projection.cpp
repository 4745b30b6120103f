#include "galerkin_projection.hpp"

#include <stdexcept>

namespace rc::modes {
namespace {

// x^H y for block vectors X, Y (pairs (Re, Im)): Re = X·Y, Im = X·JY with (JY)_{2j} = Y_{2j+1}, (JY)_{2j+1} = −Y_{2j}.
std::complex<double> block_dot(Vec X, Vec Y, Vec JY) {
  PetscScalar re = 0, im = 0;
  petsc_check(VecDot(Y, X, &re), "VecDot");
  petsc_check(VecDot(JY, X, &im), "VecDot");
  return {re, im};
}

void turn(Vec Y, Vec JY) {
  PetscInt lo = 0, hi = 0;
  petsc_check(VecGetOwnershipRange(Y, &lo, &hi), "VecGetOwnershipRange");
  const PetscScalar* y = nullptr;
  PetscScalar* j = nullptr;
  petsc_check(VecGetArrayRead(Y, &y), "VecGetArrayRead");
  petsc_check(VecGetArray(JY, &j), "VecGetArray");
  for (PetscInt g = 0; g + 1 < hi - lo; g += 2) {  // pairs never straddle ranks (viscous_forms.cpp)
    j[g] = y[g + 1];
    j[g + 1] = -y[g];
  }
  petsc_check(VecRestoreArray(JY, &j), "VecRestoreArray");
  petsc_check(VecRestoreArrayRead(Y, &y), "VecRestoreArrayRead");
}

// Rows l, columns k: x_l^H (op x_k) for the block operator `op` (Â or M̂).
Eigen::MatrixXcd projected(Mat op, const std::vector<Vec>& modes) {
  const int n = static_cast<int>(modes.size());
  Eigen::MatrixXcd P(n, n);
  PVec Y, JY;
  petsc_check(VecDuplicate(modes.front(), Y.out()), "VecDuplicate");
  petsc_check(VecDuplicate(modes.front(), JY.out()), "VecDuplicate");
  for (int k = 0; k < n; ++k) {
    petsc_check(MatMult(op, modes[k], Y), "MatMult");
    turn(Y, JY);
    for (int l = 0; l < n; ++l) P(l, k) = block_dot(modes[l], Y, JY);
  }
  return P;
}

// x_l^H y for each block vector x_l.
Eigen::VectorXcd projected(Vec y, const std::vector<Vec>& modes) {
  PVec Jy;
  petsc_check(VecDuplicate(y, Jy.out()), "VecDuplicate");
  turn(y, Jy);
  Eigen::VectorXcd out(static_cast<Eigen::Index>(modes.size()));
  for (std::size_t l = 0; l < modes.size(); ++l) out[static_cast<Eigen::Index>(l)] = block_dot(modes[l], y, Jy);
  return out;
}

}  // namespace

GalerkinMatrices project_on_modes(const ViscousForms& forms, const std::vector<Vec>& modes) {
  if (modes.empty()) throw std::runtime_error("a Galerkin projection needs at least one mode");
  GalerkinMatrices g;
  g.op = projected(forms.A, modes);
  g.gram = projected(forms.M, modes);
  g.gram = (0.5 * (g.gram + g.gram.adjoint())).eval();  // Hermitian up to rounding; made exactly so
  g.viscous = (g.op - g.op.adjoint()) / std::complex<double>(0, 2);
  g.coupling = projected(forms.coupling, modes);
  if (forms.offset_coupling.get() != nullptr) g.offset = projected(forms.offset_coupling, modes);
  return g;
}

double dissipation_mismatch(const GalerkinMatrices& g, const std::vector<std::complex<double>>& lambda) {
  const Eigen::Map<const Eigen::VectorXcd> l(lambda.data(), static_cast<Eigen::Index>(lambda.size()));
  const Eigen::MatrixXcd GL = g.gram * l.asDiagonal();
  const Eigen::MatrixXcd implied = (GL - GL.adjoint()) / std::complex<double>(0, 2);
  const double scale = g.viscous.cwiseAbs().maxCoeff();
  return scale > 0 ? (g.viscous - implied).cwiseAbs().maxCoeff() / scale : 0.0;
}

}  // namespace rc::modes
