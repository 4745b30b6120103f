// A tank row's coupling about its body's joint O_k (docs/physics.md §2): the table's for a filled tank, a + c t for a
// partially filled one. Shared by (26)'s tanks (chain_model.cpp) and the chain without axial symmetry's
// (general_tank.cpp).
#pragma once

#include "mode_table.hpp"

#include <complex>
#include <cstddef>

namespace rc::rom {

// Each row's coupling about the body's joint O_k: the table's for a filled tank, a + c t for a
// partially filled one (c = O_k -> centroid in the table's unit); complex for a viscous table (a + i a_imag, t + i
// t_imag: docs/viscous.md, "Partially filled tanks"), E_c = 2 (a + c t)² / N² then.
struct RowCoupling {
  const rc::ModeTable& t;
  double c = 0;
  double a(std::size_t l) const { return t.free_surface.present() ? t.a[l] + c * t.free_surface.t[l] : t.a[l]; }
  std::complex<double> E_c(std::size_t l) const {
    if (!t.free_surface.present()) return {t.E[l], t.viscous() ? t.E_imag[l] : 0.0};
    const std::complex<double> ac(a(l), t.viscous() ? t.a_imag[l] + c * t.free_surface.t_imag[l] : 0.0);
    return 2.0 * ac * ac / t.N2[l];
  }
  double E(std::size_t l) const { return E_c(l).real(); }
  // Σ E over every mode about O_k, in table units
  double sum_rule() const { return t.free_surface.present() ? t.sum_rule_about(c) : t.A_f - t.J_zh; }
};

}  // namespace rc::rom
