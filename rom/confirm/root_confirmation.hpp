// Roots of Kononov's characteristic equation (22) with a viscous tank's own response R(s) in place of its table's
// modes: a root found with a response-fit (or damped-mode) table is taken as the start of an iteration on
//   det Phi_true(sigma) = 0,   Phi_true = Phi without the viscous tanks' modes − diag_k( rho L^5 s_k R_k(s_k) ),
// s_k = (sigma + omega_k)/omega_k (docs/rom.md, "Confirmed roots"). R_k comes from anywhere that evaluates it at a
// complex s (forced solves of the Navier–Stokes problem: served_response.hpp; a closed form in the tests). The first
// step is Newton's with the table's derivative of Phi, the rest are secant steps on det Phi_true: no derivative of
// R is needed, and one evaluation of every viscous tank's R per step.
#pragma once

#include "chain_model.hpp"

#include <complex>
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace rc::rom {

// One viscous tank's response in its table's units (rho = 1, omega0 = 1 > 0): R(s) = sum_l E_l/(s - lambda_l).
struct TankResponse {
  int body = 0;                                          // 0-based
  double rho_L5 = 0;                                     // density * scale^5: table units -> kg m^2
  std::function<std::complex<double>(std::complex<double>)> R;
  // A partially filled tank (docs/viscous.md, "The response of a partially filled tank"): R about the liquid's centroid
  // and its offset parts (R, R_fg, R_gg) at s, in place of R; and the offset row g over the chain's coordinates (the
  // extended chain's on a free chain, base_translation.hpp), in table lengths: the centroid's offset from its joint
  // on its own body, the joints' lengths s_j on the earlier ones, 1 per unit of the base's translation. The tank
  // answers the form R e eᵀ + R_fg (e gᵀ + g eᵀ) + R_gg g gᵀ (e its own body), docs/physics.md §2.
  std::function<std::array<std::complex<double>, 3>(std::complex<double>)> R_offset;
  Eigen::VectorXd offset_row;
  // The liquid is symmetric about its mid-plane (a built-in sphere, spheroid or cylinder, whose free surface is a
  // coaxial cylinder): R_fg vanishes, and what the forced solves give of it measures the mesh's own asymmetry.
  bool mirror_symmetric = false;
};

struct ConfirmSettings {
  double tolerance = 1e-10;  // the last step below tolerance * |sigma|: converged
  int max_steps = 30;
};

struct ConfirmedRoot {
  std::complex<double> start;   // the table's root
  std::complex<double> sigma;   // the root of (22) with R itself (the last iterate when not converged)
  int evaluations = 0;          // evaluations of Phi_true (each one R per viscous tank)
  bool converged = false;
  std::string failure;          // why not, in a few words
  double moved() const { return std::abs(sigma - start) / std::max(std::abs(sigma), 1e-300); }
};

// The model's Phi (22) with R_k in place of each listed body's modes and static-correction remainder. A negative spin
// mirrors the flow as chain_model.cpp does: the body's term is then rho L^5 s conj(R(conj(s))).
Eigen::MatrixXcd characteristic_matrix_with(const ChainModel& m, const std::vector<TankResponse>& tanks,
                                            std::complex<double> sigma);

// The iteration from `start`. Throws nothing of its own; an exception from R (a failed forced solve) propagates.
ConfirmedRoot confirm_root(const ChainModel& m, const std::vector<TankResponse>& tanks, std::complex<double> start,
                           const ConfirmSettings& settings = {});

// A root as confirm's lines print it: 10 significant digits, "re + imi" (or "re - |im|i").
std::string root_text(std::complex<double> z);

}  // namespace rc::rom
