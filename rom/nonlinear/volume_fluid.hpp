// The liquid of tanks without axial symmetry in the nonlinear chain (docs/rom.md, "Nonlinear chain", "Tanks without
// axial symmetry"): each kept mode of a body's tanks as complex coupling vectors c, c_left (body axes; H = c c_leftᵀ in
// kg m², as the general chain has it, general_tank.hpp: c_left = c̄ for the ideal fluid) and the tanks' λ = 0 weight
// G, in the body's frame at any attitude:
//   ż = iλ z − c_left·Ω̇,  λ = r λ_table + i|r| decay_table (r = Ω·e3 the body's spin),   h = Σ 2 Re(z c) − G (Ω − ω_ref e3),
// and the liquid acts on the body with the moment −(ḣ + Ω × h). The general chain's tank model (ż = iλz − c_left·δω̇,
// h = Σ 2Re(zc) − G δω, moment −(ḣ + ω0 e_z × h)) is this one linearised about the steady spin ω_ref; for an
// axisymmetric tank it is the existing body-frame model (nonlinear_chain.hpp, ChainFluidMode) with the axial part
// of Ω × h kept. With the ideal fluid the body's angular momentum about O_k is J Ω + h, an integral of a free body; a
// damped mode (viscous table) dissipates, its decay taken at the table's Ekman number (the spin may not move far from
// the scene's: nonlinear_run.hpp reports how far it did).
#pragma once

#include "eigen_dense.hpp"

#include <cmath>
#include <complex>
#include <vector>

namespace rc::rom {

struct ChainVolumeMode {
  Eigen::Vector3cd c = Eigen::Vector3cd::Zero();       // kg^{1/2} m, body axes
  Eigen::Vector3cd c_left = Eigen::Vector3cd::Zero();  // kg^{1/2} m, body axes (c̄ for the ideal fluid)
  double lambda_table = 0;                              // Re λ / r
  double decay_table = 0;                               // Im λ / |r| (0 for the ideal fluid)
  std::complex<double> lambda(double spin) const { return {spin * lambda_table, std::abs(spin) * decay_table}; }
};

struct VolumeFluid {
  std::vector<ChainVolumeMode> modes;
  Eigen::Matrix3d geostrophic = Eigen::Matrix3d::Zero();  // G (kg m², real symmetric), body axes
  double reference_spin = 0;                              // ω_ref: the spin about which G's fluid stays at rest
  Eigen::Matrix3d share = Eigen::Matrix3d::Zero();        // Σ 2 Re(c c_leftᵀ) + G: the part of the frozen inertia
                                                          // the liquid does not carry rigidly (set by finish());
                                                          // not symmetric with a damped mode
  int size() const { return static_cast<int>(modes.size()); }
  bool present() const { return !modes.empty() || !geostrophic.isZero(); }
  void finish();
};

// h (body axes) for the body's angular velocity Ω (body axes) and the modes' amplitudes z[0 .. size()).
Eigen::Vector3d volume_momentum(const VolumeFluid& f, const Eigen::Vector3d& Omega, const std::complex<double>* z);

// The liquid's moment on the body (body axes) without its −share·Ω̇ part, which the mass matrix carries:
// −Σ 2 Re(iλ z c) − Ω × h.
Eigen::Vector3d volume_moment(const VolumeFluid& f, const Eigen::Vector3d& Omega, const std::complex<double>* z);

// ż for every mode, appended to `out`, given Ω̇ (body axes).
void volume_rates(const VolumeFluid& f, const Eigen::Vector3d& Omega, const Eigen::Vector3d& Omega_dot,
                  const std::complex<double>* z, std::vector<std::complex<double>>& out);

}  // namespace rc::rom
