// A test's response-fit table: a viscous table (the sphere's of make_viscous_tables.sh) with its rows replaced by the
// given poles and residues (N² = 1, a = √(E/2)), on the window s ∈ [−1.5, 2] with the given fit error.
#pragma once

#include "closed_form_tables.hpp"
#include "mode_table.hpp"

#include <complex>
#include <string>
#include <vector>

namespace rc::rom::test {

inline rc::ModeTable response_fit_rows(rc::ModeTable t, const std::vector<std::complex<double>>& poles,
                                       const std::vector<std::complex<double>>& residues, double fit_error) {
  t.galerkin = {};  // a response fit's poles are no modes
  t.lambda.clear(); t.kappa.clear(); t.decay.clear(); t.E.clear(); t.E_imag.clear(); t.a.clear(); t.a_imag.clear();
  t.N2.clear(); t.residual.clear(); t.spread.clear(); t.members.clear(); t.dlambda.clear(); t.dE.clear();
  t.converged.clear();
  for (std::size_t l = 0; l < poles.size(); ++l) {
    t.lambda.push_back(poles[l].real());
    t.kappa.push_back(2 / poles[l].real());
    t.decay.push_back(poles[l].imag());
    t.E.push_back(residues[l].real());
    t.E_imag.push_back(residues[l].imag());
    const std::complex<double> a = std::sqrt(residues[l] / 2.0);
    t.a.push_back(a.real());
    t.a_imag.push_back(a.imag());
    t.N2.push_back(1);
    t.residual.push_back(0);
  }
  t.fit_lo = -1.5;
  t.fit_hi = 2;
  t.fit_error = fit_error;
  return t;
}

// The same written as RC_VISCOUS_TABLES/name (the executable's folder of make_viscous_tables.sh's tables); returns
// the file's path.
inline std::string write_response_fit(const std::vector<std::complex<double>>& poles,
                                      const std::vector<std::complex<double>>& residues, double fit_error,
                                      const std::string& name) {
  const std::string file = std::string(RC_VISCOUS_TABLES) + "/" + name;
  write_table(response_fit_rows(rc::read_mode_table(std::string(RC_VISCOUS_TABLES) + "/sphere_ek1e-3.h5"), poles,
                                residues, fit_error),
              file);
  return file;
}

}  // namespace rc::rom::test
