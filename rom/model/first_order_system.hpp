// First-order form of system (26) (Kononov) in the state y = (s u, u-dot, w), with
//   w_kl = z_kl + u-dot_k,   S'_kl = (a_kl / N_kl^2) z_kl,
// z being the fluid coordinate scaled to angular-velocity units (docs/rom.md, "scaling"). Then
//   M_eff u'' = -K u - (i Gamma + D) u' + i sum_l E_kl nu_kl w_kl,   Gamma_k = C_k w_k0 - sum_l E_kl lambda_kl,
//   w_kl'    = -i nu_kl w_kl - i lambda_kl u_k',                   nu_kl = w_k0 - lambda_kl,
// with M_eff = M - diag(sum_l E_kl) — only E_kl enters, never a_kl or N_kl alone. With a viscous tank
// E_kl and lambda_kl are complex (lambda_c = lambda + i decay, E_c the residue; docs/rom.md "Viscous tanks"):
// the same equations hold unchanged, B is then truly complex and M_eff may be complex symmetric.
// s is a frequency scale that balances the u and u-dot blocks. Roots: y ~ e^{i sigma t},
// i.e. sigma = -i * eigenvalue(B).
#pragma once

#include "chain_model.hpp"

#include "eigen_dense.hpp"
#include <complex>

namespace rc::rom {

struct FirstOrderSystem {
  int n = 0, nm = 0;
  double s = 1;          // u is carried as s*u
  Eigen::MatrixXcd B;    // y' = B y
  int dim() const { return 2 * n + nm; }
  // Physical state (u, u-dot, z) <-> balanced state y.
  Eigen::VectorXcd to_state(const ChainModel& m, const Eigen::VectorXcd& u, const Eigen::VectorXcd& v,
                            const Eigen::VectorXcd& z) const;
  void from_state(const ChainModel& m, const Eigen::VectorXcd& y, Eigen::VectorXcd& u,
                  Eigen::VectorXcd& v, Eigen::VectorXcd& w) const;
};

FirstOrderSystem build_first_order(const ChainModel& m);

// The fluid coordinates z from the bodies' rates v and the fluid states w: z_l = w_l − w_lᵀu̇ (minus the base's share
// on a free chain with a partially filled tank, base_translation.hpp).
Eigen::VectorXcd fluid_coordinates(const ChainModel& m, const Eigen::VectorXcd& v, const Eigen::VectorXcd& w);

// The matrix B of build_first_order assembled in the arithmetic of Real (double or long double) for
// the balancing scale s, from the model's (double) M_eff, K, D, G, E, lambda, nu: what the
// extended-precision reference of `chain-rom bench` propagates (reference_propagation.hpp).
// The trace of B without building it (root_tracking.hpp checks its roots' sum against it):
//   tr B = -tr(M_eff^{-1} (i Gamma + D)) - i sum_l nu_kl.
std::complex<double> first_order_trace(const ChainModel& m);

template <class Real>
Eigen::Matrix<std::complex<Real>, Eigen::Dynamic, Eigen::Dynamic> first_order_matrix(const ChainModel& m, Real s);

}  // namespace rc::rom
