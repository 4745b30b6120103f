// The linear chain without axial symmetry (docs/rom.md, "Bodies and tanks without axial symmetry"): bodies with
// B ≠ A or products of inertia, tanks from 3-D tables (docs/volume.md). Such a body's coefficients are constant only
// in a frame that turns with it, so the chain is written in the frame F turning at the bodies' common spin ω0 about the
// vertical, in real coordinates: q_k = (n_x, n_y) the tip of body k's axis in F (u_k = e^{−iω0t}(q_x − i q_y), u the
// complex tilt of (26)), and, when a tank ties the tilt to the spin, the bodies' axial rates ψ̇_k. Without the fluid's
// modes the chain is the second-order system
//   M Q̈ + C Q̇ + K Q = 0,
// (26) carried into F for the axisymmetric part (docs/rom.md gives the algebra) plus each body's anisotropy
// Δ_k = I_tt − Ā_k I (the transverse inertia tensor less its mean): −Δ_k (q̈_k + ω0² q_k). The modes enter through
// each body's relative angular momentum h_k (general_system.hpp).
#pragma once

#include "chain_model.hpp"
#include "scene.hpp"
#include "general_tank.hpp"

#include "eigen_dense.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rc::rom {

struct GeneralChain {
  int n = 0;
  double spin = 0;          // ω0 (rad/s): the frame's rate, the first spin of a body that turns it (else body[1]'s)
  Eigen::VectorXd spins;    // each body's spin (rad/s); body k turns against F at ω_k − ω0
  double period = 0;        // 2π/|ω_k − ω0| when a body without axial symmetry or with tanks turns against F, else 0
  std::vector<Eigen::Matrix2d> anisotropy;  // per body: Δ_k = I_tt − Ā_k I at t = 0 (body axes on F's), in M and K
  bool axial = false;       // the axial rates are coordinates (some tank is 3-D: its modes may couple to the spin)
  bool free_chain = false;
  Eigen::MatrixXd M, C, K;  // in Q = (q_1, …, q_n[, ψ_1, …, ψ_n]): the frozen fluid's inertia included, no modes
  Eigen::VectorXd axial_inertia;  // C_k with the frozen fluid (kg m²)
  std::vector<Eigen::Matrix3d> geostrophic;  // per body: the 3-D tanks' λ = 0 weight (kg m²), else 0
  std::vector<GeneralMode> modes;            // every tank's kept modes, body by body
  std::vector<std::pair<int, double>> coverage;  // per tank, body by body: (body, its kept share of the sum rule)
  std::vector<std::pair<int, int>> pruned_rows;  // (body, rows) per tank whose response table had rows left out
  std::vector<std::string> not_converged;        // per partially filled 3-D tank with unsettled rows: what to say
  bool dissipative = false;                  // joint or axial friction, a viscous tank: roots leave the real axis
  double response_window = 0;                // the narrowest response table's window (rad/s, |Re σ|); 0: none
  // A free chain with partially filled 3-D tanks (free_recoil.hpp): the same chain extended by its base's translation X,
  // from which build_general_system reduces this one's first-order form.
  std::shared_ptr<const GeneralChain> recoil;
  // In that extended chain: body n − 1 is the base X (q = X, tilt-like maps, no spin, no axial rate), and the base's
  // rows of the λ = 0 weight against each body's velocities (3 × 3(n − 1)) and of the kinetic form against every
  // velocity (3 × 3n: the bodies' first moments, the total mass, the tanks' surface parts), whose product with the
  // velocities is its transverse momentum (turned by J).
  bool base = false;
  Eigen::MatrixXd base_geostrophic, base_form;
  int spinning() const { return base ? n - 1 : n; }  // the bodies with an axial rate (with `axial`)
  int dim_q() const { return 2 * n + (axial ? spinning() : 0); }
  bool periodic() const { return period > 0; }  // Floquet: floquet.hpp
  int n_modes() const { return static_cast<int>(modes.size()); }
};

// A body with its tanks: mass, centre of mass along its axis, its full inertia tensor about O_k (body axes, frozen
// liquid included) and its tanks. Throws SceneError naming the key for a table that cannot be read, a tank the
// general chain does not take (general_tank.hpp), a centre of mass off the axis or products I_xz, I_yz (the body could
// not spin steadily about its axis).
struct GeneralBody {
  double mass = 0, com = 0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  std::vector<GeneralTank> tanks;
};
std::vector<GeneralBody> general_bodies(const Scene& scene, TableCache& tables);

// True when the scene needs the general chain: some body with B ≠ A or products of inertia, several tanks, a tank off
// its body's axis or a tank whose table is 3-D. Reads the tables through `tables` (throws SceneError naming the key on a table that cannot be read).
bool needs_general_chain(const Scene& scene, TableCache& tables);

// Bodies at different spins: F turns with the first body without axial symmetry or with tanks (else body[1]). An
// axisymmetric body without tanks may spin at its own rate (its coefficients do not depend on its angle); a second
// spin among the others makes the coefficients periodic (periodic_system.hpp, floquet.hpp; docs/rom.md, "Bodies at
// different spins"), a third quasi-periodic (refused). `frame` puts F at another rate (tests: the same chain seen
// from a frame it turns against). Throws SceneError naming the key for what the general chain does not take yet
// (three spins, aerodynamic, external moments and forces, fields, Galerkin tanks, partial fills off the first body's
// axis or on a moving joint), for a body
// whose products of inertia with its frozen fluid do not vanish (it cannot spin steadily about its axis), and when the
// effective inertia with the modes' share taken out is not positive definite.
GeneralChain build_general_chain(const Scene& scene, TableCache* tables = nullptr,
                                 std::optional<double> frame = std::nullopt);

// (26) carried into the turning frame (u = e^{−iω0t} v) for `cm`'s coordinates, each body's anisotropy from `inertia`
// (one per spinning body) and, with axial rates, the spins' block from `axial`'s bodies: g's M, C, K and anisotropy.
void set_turning_frame_matrices(const ChainModel& cm, const ChainModel& axial, const std::vector<Eigen::Matrix3d>& inertia,
                                GeneralChain& g);

}  // namespace rc::rom
