// A tank in a body of the chain without axial symmetry (docs/rom.md, "Bodies and tanks without axial symmetry"):
// its frozen fluid as a 3 × 3 inertia tensor about the body's joint O_k, the weight of the fluid that stays at rest
// while the body turns (λ = 0), and each kept mode as a frequency with a complex coupling vector. From a 3-D table
// (cavity-modes ellipsoid / volume: docs/volume.md §5) or an axisymmetric one, anywhere on or off the body's axis.
#pragma once

#include "mode_table.hpp"
#include "scene.hpp"

#include "eigen_dense.hpp"

#include <complex>
#include <string>
#include <vector>

namespace rc::rom {

// One fluid mode of the general chain: the flow z V e^{iλt} in its body's frame (its conjugate at −λ̄ is the same real
// motion), forced by the body's angular acceleration and moving the body through its angular momentum
// (docs/rom.md, "Bodies and tanks without axial symmetry"):
//   ż = iλ z − c_left·δω̇,   h = 2 Re(z c),   H = c c_leftᵀ.
// Ideal fluid: λ real, c_left = c̄ (c_j = ρ∫(e_j × r)·V, ρ∫|V|² = 1, so that H = c cᴴ in kg m²). Viscous fluid
// (docs/volume.md §7): λ = ω_k0 λ_table + i|ω_k0| decay_table decays, and c, c_left come from the right and left
// eigenvectors (H = (fᵀx)(fᵀy)ᵀ, not Hermitian).
struct GeneralMode {
  int body = 0;                 // 0-based body index
  int table_row = 0;            // the table's row it comes from (reduction = "bands": its band)
  std::complex<double> lambda;  // rad/s: ω_k0 λ_table (Kononov (21)), + i|ω_k0| decay_table for a viscous mode
  double lambda_table = 0;      // λ / ω_k0 (the table's, for a unit spin)
  double decay_table = 0;       // the table's decay (viscous tables; 0 for the ideal fluid)
  Eigen::Vector3cd c;           // kg^{1/2} m
  Eigen::Vector3cd c_left;      // kg^{1/2} m
  // A partially filled 3-D tank's mode in a free chain: its coupling to the base's translation, through the T̂
  // directions' amplitude τ = J V (V the joint's velocity in F; docs/volume.md §8, "The free chain"); else 0.
  Eigen::Vector2cd c_base = Eigen::Vector2cd::Zero();       // kg^{1/2}
  Eigen::Vector2cd c_left_base = Eigen::Vector2cd::Zero();  // kg^{1/2}
  bool damped() const { return decay_table > 0; }
};

struct GeneralTank {
  bool three_d = false;     // from a 3-D table (its modes may couple to the spin)
  double mass = 0;          // kg
  double scale = 0;         // its length unit L (m)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // O_k -> the fluid's centroid, body axes (m)
  Eigen::Matrix3d inertia;  // the frozen fluid's inertia tensor about O_k (kg m²), body axes
  Eigen::Matrix3d geostrophic;  // the λ = 0 weight (kg m², real symmetric): fluid that does not follow the body
  std::vector<GeneralMode> modes;
  double window = 0;        // a response table's: |Re σ| (rad/s, turning frame) up to which it is the fluid's R; 0: none
  double coverage = 0;      // the kept rows' E (and the λ = 0 weight's transverse half) over the table's sum rule
  // A partially filled 3-D tank's kept rows whose λ did not settle (their bound above the survey's tolerance: a dense
  // cluster's weight, docs/volume.md §8), and the largest such bound relative to max(|λ|, 0.1).
  int unsettled_rows = 0;
  int pruned_rows = 0;      // a response table's rows left out as no root needs them (response_row_pruning.hpp)
  double worst_bound = 0;
  // A 3-D partial fill in a free chain (free_recoil.hpp): its re-centring form and λ = 0 weight over the velocities
  // (δω_x, δω_y, δω_z, τ_x, τ_y) about the joint, τ = J V the base's translation as its T̂ directions see it. Their
  // first 3 × 3 blocks are in `inertia` and `geostrophic`.
  bool recoil = false;
  Eigen::Matrix<double, 5, 5> surface_form = Eigen::Matrix<double, 5, 5>::Zero();      // kg m² (blocks with τ: kg m, kg)
  Eigen::Matrix<double, 5, 5> geostrophic_form = Eigen::Matrix<double, 5, 5>::Zero();
};

// Body k's tank `cav` (scene key `where`) from its table. Rows kept as for an axisymmetric tank (every coupling one,
// or the first `modes` by E, or as many as reach `coverage` of the sum rule); a 3-D row's H is split into rank-one
// couplings (a row sums a cluster of discrete copies: H = Σ c cᴴ); an axisymmetric m = 1 row is c = √(E/2) (1, i, 0)
// (H_xy = −i H_xx, measured on a 3-D spheroid's table), its frozen fluid diag(A_f, A_f, C_f) and its λ = 0 weight
// the axial C_f (ideal fluid does not spin up). Placement: the centroid at (offset, center), or with `origin` the
// table's origin at (offset, origin). A viscous table (axisymmetric or 3-D) needs the scene's viscosity at its Ekman
// number (check_viscosity); its rows are single damped modes whose H = c c_leftᵀ is of rank one. Throws SceneError
// naming the key for the static correction, a Galerkin reduction, a companion table, a partially filled tank elsewhere
// than on the chain's first body (a 3-D partial fill's table taken there on the spin axis it was made for: its five
// directions about the joint, docs/volume.md §8, in a fixed or a free chain; an axisymmetric one on the body's axis of a
// fixed chain), a 3-D viscous table on a body spinning the other way (its mirror image is another cavity) or
// a viscous row whose coupling tensor is not of rank one.
GeneralTank general_tank(const Scene& scene, int k, const CavitySpec& cav, const std::string& where,
                         const rc::ModeTable& t);

}  // namespace rc::rom
