#include "coupling.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rc::modes {

ModeCoupling coupling_from_forms(double lambda, double f1p, double f2p, double kh, double gc, double kz) {
  const double l = lambda, D = 4 - l * l;
  // With the real representation V = (i a, b, i c) e^{iφ} of an m = 1 field, the physical inner products
  // are (U, V) = π ∫∫ U·V r dr dz and ‖V‖² = 2π ∫∫ |V|² r dr dz (docs/physics.md §2). For Ṽ:
  const double coupling = std::numbers::pi * ((l * l + 2 * l) * f1p + D * f2p);
  const double t1 = l * l * (l * l + 4) * kh, t2 = 4 * l * l * l * gc,
               t3 = D * D * kz;
  const double norm2 = 2 * std::numbers::pi * (t1 + t2 + t3);
  if (!std::isfinite(norm2) || !std::isfinite(coupling))
    throw std::runtime_error("eigenvector with non-finite kinetic energy");
  ModeCoupling c;
  // Ṽ vanishes (to rounding) only for λ = 0 with Kz p = 0: a steady geostrophic field, which carries no E.
  if (norm2 <= 1e-14 * 2 * std::numbers::pi * (t1 + std::abs(t2) + t3)) return c;
  c.a = coupling / std::sqrt(norm2);
  c.N2 = 1.0;
  c.E = 2 * c.a * c.a / c.N2;
  return c;
}

CouplingEvaluator::CouplingEvaluator(const PoincareForms& forms) : forms_(forms) {
  petsc_check(VecDuplicate(forms.f1, work_.out()), "VecDuplicate");
}

ModeCoupling CouplingEvaluator::evaluate(double lambda, Vec p) const {
  auto quadratic = [&](Mat A) {
    PetscScalar s = 0;
    petsc_check(MatMult(A, p, work_), "MatMult");
    petsc_check(VecDot(p, work_, &s), "VecDot");
    return static_cast<double>(s);
  };
  auto linear = [&](Vec f) {
    PetscScalar s = 0;
    petsc_check(VecDot(f, p, &s), "VecDot");
    return static_cast<double>(s);
  };
  return coupling_from_forms(lambda, linear(forms_.f1), linear(forms_.f2), quadratic(forms_.Kh),
                             quadratic(forms_.Gc), quadratic(forms_.Kz));
}

}  // namespace rc::modes
