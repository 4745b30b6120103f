// The viscous rotating fluid in a full sphere or a spherical shell (both walls no-slip), as poloidal and toroidal
// scalars expanded in spherical harmonics Y_l^m and, along the radius, Chebyshev polynomials: the spectral
// discretisation of M. Rieutord and L. Valdettaro, "Inertial waves in a rotating spherical shell" (J. Fluid Mech.
// 341, 1997), written with the ultraspherical operators of ultraspherical.hpp as in Kore (Y. Rekier, A. Trinh,
// S. Triana, V. Dehant, "Inertial modes in near-spherical geometries", 2019; github.com/repepo/kore).
//
// With u = ∇×(T r) + ∇×∇×(P r), T = Σ T_l(r) Y_l^m, P = Σ P_l(r) Y_l^m, time e^{s t}, Ω = ẑ, Ek = ν/(ΩR²) and
// c_l = √((l² − m²)/(4l² − 1)), L = l(l+1), D_l = ∂_r² + (2/r)∂_r − L/r², the radial components of the curl and
// of the curl of the curl of s u + 2ẑ × u = −∇p + Ek ∇²u are (docs/spherical.md §2 derives them):
//   s L T_l = Ek L D_l T_l + 2im T_l + 2c_l (l−1)(l+1) [P′_{l−1} − (l−1) P_{l−1}/r]
//                                  + 2c_{l+1} l(l+2) [P′_{l+1} + (l+2) P_{l+1}/r]
//   s L D_l P_l = Ek L D_l² P_l + 2im D_l P_l − 2c_l (l−1)(l+1) [T′_{l−1} − (l−1) T_{l−1}/r]
//                                            − 2c_{l+1} l(l+2) [T′_{l+1} + (l+2) T_{l+1}/r]
// multiplied by r² and r⁴ so that every coefficient is a polynomial; no-slip walls: T_l = P_l = P′_l = 0. The
// toroidal equation is written in C^(2), the poloidal one in C^(4), and their last rows give way to the wall
// conditions (the tau method), which are placed first in each block (docs/spherical.md §3: the diagonal MUMPS
// pivots on). A full sphere has its centre inside [-1, 1] (r = x): each scalar has the parity of
// its l, and only those Chebyshev polynomials are kept; a shell maps [r_i, 1] onto [-1, 1].
//
// The pencil is the one viscous/viscous_forms.hpp solves: A x = λ 𝓜 x with e^{iλt} (s = iλ: Re λ the frequency in
// the rotating frame, positive retrograde for m = 1; Im λ the decay rate), A = −i(right-hand sides), 𝓜 = the
// left-hand sides (real; zero on the tau rows).
#pragma once

#include "block_pencil.hpp"

#include <vector>

namespace rc::modes::spherical {

struct ShellSettings {
  double inner_radius = 0;     // 0: the full sphere; else the shell r_i < r < 1
  double ekman = 1e-3;
  int m = 1;                   // azimuthal wavenumber
  bool toroidal_first = true;  // T_m, P_{m+1}, T_{m+2}, … (the spin-over mode's symmetry); else P_m, T_{m+1}, …
  int radial = 48;             // Chebyshev coefficients per scalar (the full sphere: of its parity, degrees < 2·radial)
  int lmax = 48;               // the highest harmonic degree kept
};

struct ShellPencil {
  int size = 0;                  // complex unknowns: (lmax − m + 1) × radial
  Triplets a_real, a_imag, mass; // A = a_real + i a_imag, 𝓜 = mass
  std::vector<int> degree;       // l of each block of `radial` unknowns
  std::vector<bool> toroidal;    // whether that block is T_l (else P_l)
};

// Throws std::invalid_argument for settings that describe no problem (radial < 8, lmax < m + 1, inner radius
// outside [0, 1), Ek ≤ 0).
ShellPencil assemble_shell_pencil(const ShellSettings& settings);

}  // namespace rc::modes::spherical
