#include "shell_response.hpp"

#include "gauss_rules.hpp"
#include "shell_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rc::modes::spherical {
namespace {

// The Chebyshev degree of local coefficient j of the l = 1 scalar (shell_pencil.cpp's layout: the full sphere keeps
// the odd degrees, r = x; a shell all degrees, r = scale x + shift).
int degree_of(const ShellSettings& s, int j) { return s.inner_radius == 0 ? 2 * j + 1 : j; }

// w: T_1 = r in the coefficients of block 0 (the sphere: T_1(x) = x; a shell: shift T_0 + scale T_1).
std::vector<double> rigid_rotation(const ShellSettings& s, int size) {
  std::vector<double> w(size, 0.0);
  if (s.inner_radius == 0) {
    w[0] = 1;
  } else {
    w[0] = (1 + s.inner_radius) / 2;
    w[1] = (1 - s.inner_radius) / 2;
  }
  return w;
}

// 𝓜_s w from the pencil's (row-equilibrated) mass triplets: the forcing in the equations as they are solved.
std::vector<double> mass_times(const ShellPencil& p, const std::vector<double>& w) {
  std::vector<double> b(p.size, 0.0);
  for (std::size_t k = 0; k < p.mass.v.size(); ++k) b[p.mass.i[k]] += p.mass.v[k] * w[p.mass.j[k]];
  return b;
}

// g with π gᵀx = (8π/3) ∫ r³ T_1(r) dr: g_j = (8/3) ∫ r³ T_{d(j)}(x(r)) dr by Gauss–Legendre, exact for the
// polynomial integrand (degree below 2·radial + 4).
std::vector<double> pairing_with_w(const ShellSettings& s, int size) {
  const double lo = s.inner_radius, hi = 1;
  std::vector<double> x, wq;
  gauss_legendre(s.radial + 8, x, wq);
  std::vector<double> g(size, 0.0);
  for (std::size_t q = 0; q < x.size(); ++q) {
    const double r = lo + (hi - lo) * (x[q] + 1) / 2, dr = wq[q] * (hi - lo) / 2;
    const double xi = s.inner_radius == 0 ? r : 2 * (r - lo) / (hi - lo) - 1;  // the Chebyshev variable
    for (int j = 0; j < s.radial; ++j)
      g[j] += 8.0 / 3.0 * std::pow(r, 3) * std::cos(degree_of(s, j) * std::acos(std::clamp(xi, -1.0, 1.0))) * dr;
  }
  return g;
}

}  // namespace

ShellResponse::ShellResponse(const ShellSettings& s, MPI_Comm comm) {
  if (s.m != 1 || !s.toroidal_first)
    throw std::invalid_argument("the tilt forces the m = 1 flow that is antisymmetric about the equator only");
  const ShellPencil pencil = assemble_shell_pencil(s);
  if (pencil.degree.front() != 1 || !pencil.toroidal.front()) throw std::logic_error("block 0 is not T_1");
  forms_ = shell_forms(pencil, comm);
  forms_.coupling = block_vector(forms_.A, mass_times(pencil, rigid_rotation(s, pencil.size)));
  output_ = block_vector(forms_.A, pairing_with_w(s, pencil.size));
  petsc_check(VecDuplicate(forms_.coupling, x_.out()), "VecDuplicate");
  solver_ = std::make_unique<ShiftedSolver>(forms_);
}

ShellResponse::~ShellResponse() = default;

std::complex<double> ShellResponse::operator()(std::complex<double> sigma) {
  solver_->factor(sigma);
  solver_->solve(forms_.coupling, x_);
  return std::numbers::pi * block_bilinear(output_, x_);
}

}  // namespace rc::modes::spherical
