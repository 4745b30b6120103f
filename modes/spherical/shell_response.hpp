// The moment response of the fluid in a full sphere or a spherical shell to the cavity's tilt, by forced solves of the
// spectral pencil (shell_pencil.hpp): the function the finite elements' forced solves give (viscous_response.hpp,
// docs/viscous.md §6), on a discretisation that resolves the Ekman layers and the shear layers with a few hundred
// polynomials (docs/spherical.md, "Forced response").
//
// The tilt forces the flow through the rigid rotation about a horizontal axis, W = e1 × r, whose m = 1 part is the
// toroidal scalar T_1 = r (the inviscid spin-over mode). The finite elements' R(σ) = π fᵀ(σ𝓜 − A)⁻¹f has f = 𝓜W
// (docs/viscous.md §1: f(v) = ∫∫(−z v− + r v_z) r dr dz is W's 𝓜-product with v), so it is the response of the flow
// to the body force W paired with W itself. In the spectral pencil the same forcing enters the toroidal l = 1
// equation as 𝓜_s w (w: the coefficients of T_1 = r), and the pairing with W keeps only the solution's toroidal l = 1
// scalar (the spherical harmonics are orthogonal, toroidal and poloidal fields too):
//   R(σ) = (8π/3) ∫ r³ T_1(r) dr  over the fluid's radii,  T_1 from (σ𝓜_s − A) x = 𝓜_s w.
// The constant 8π/3 makes the inviscid limit the frozen fluid's E = (8π/15)(1 − r_i⁵): there x = w/(σ − 1) and
// (8π/3) ∫ r⁴ dr = (8π/15)(1 − r_i⁵), the spin-over mode's E of docs/physics.md §2 (checked in the tests against the
// finite elements' R at Ek = 1e-3, which shares no code with this file but the factorisation).
#pragma once

#include "shell_pencil.hpp"
#include "shifted_solver.hpp"
#include "viscous_forms.hpp"

#include <mpi.h>

#include <complex>
#include <memory>

namespace rc::modes::spherical {

class ShellResponse {
 public:
  // Throws std::invalid_argument for settings the tilt does not force (m != 1, or the equatorially symmetric flow:
  // W is antisymmetric) and for those assemble_shell_pencil refuses.
  ShellResponse(const ShellSettings& settings, MPI_Comm comm);
  ~ShellResponse();
  ShellResponse(const ShellResponse&) = delete;
  ShellResponse& operator=(const ShellResponse&) = delete;

  // R(σ) at a complex frequency σ (e^{iσt}, the rotating frame: the conventions of docs/viscous.md). Throws
  // std::runtime_error when the factorisation fails (σ on a damped mode).
  std::complex<double> operator()(std::complex<double> sigma);

  long complex_unknowns() const { return forms_.complex_size; }

 private:
  ViscousForms forms_;
  PVec output_;  // the pairing with W: R = π outputᵀ x
  PVec x_;
  std::unique_ptr<ShiftedSolver> solver_;
};

}  // namespace rc::modes::spherical
