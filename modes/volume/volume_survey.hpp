// The modes of a 3-D cavity that couple to the body's rotation, by a block Lanczos Gauss rule of the coupling's
// matrix-valued spectral measure (docs/volume.md §2; the 3-D form of modes/ideal/spectral_survey.hpp).
//
// The start block is the three solenoidal rotation fields w_k = P_H(e_k × r) and the same times i (the real form
// of a complex space). A mode l with velocity V_l (‖V_l‖ = 1) couples to rotation about e_k through
// c_lk = ∫ (e_k × r)·V_l dτ; the measure's weight at λ_l is the Hermitian coupling tensor H_l = c_l c_lᴴ, and
//   Σ_l H_l = Gram(w) = I_f − J_zh      (the tensor sum rule: frozen inertia minus Zhukovsky's, about the centroid),
// over every mode of both signs of λ. A mode at λ and its complex conjugate at −λ are one real motion:
// H(−λ) = conj H(λ) (complex conjugation takes A to −A and the start block to itself, so the rule is exactly
// symmetric), and a table keeps λ > 0 only. The weight at λ = 0 (geostrophic motions, e.g. an ellipsoid's
// steady axial vortex) is reported apart.
#pragma once

#include "block_lanczos.hpp"
#include "stiffness_solver.hpp"
#include "volume_velocity.hpp"

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace rc::modes {

using Hermitian3 = Eigen::Matrix3cd;

struct VolumeMode {
  double lambda = 0;
  Hermitian3 H = Hermitian3::Zero();  // coupling tensor Σ c cᴴ over the cluster's Ritz values
  double spread = 0;                  // trace-weighted spread of λ inside the cluster
  int members = 0;                    // Ritz values (each complex mode counts once)
  double residual = 0;                // largest Ritz residual bound among the members
  double dlambda = 0, dH = 0;         // change since the previous check (absolute λ, relative H)
};

struct VolumeSurveySettings {
  int max_columns = 60;           // plain survey: basis vectors in all (6 per block); it only locates the heavy
                                  // weight, which the shifts then resolve
  int shift_columns = 360;        // each shift-and-invert run: the same
  double window = 2e-3;           // a shift's window: |λ − σ| <= window · max(|σ|, 0.1)
  int check_every = 2;            // compare the rule every this many blocks
  double lambda_tolerance = 1e-10;  // settled: λ moved less than this · max(|λ|, 0.1) ...
  double weight_tolerance = 1e-8;   // ... and H less than this (relative) between two checks
  double residual_tolerance = 1e-8; // and ‖(A − λ)z‖ below this · max(|λ|, 0.1): a node's λ is good to about
                                    // the residual² over the gap to the next eigenvalue, which is small in a
                                    // dense spectrum (measured: 1e-5 let a Gauss node 4e-6 off pass)
  double merge_width = 1e-5;        // Ritz values closer than this · max(|λ|, 0.1) form one cluster (as the
                                    // axisymmetric tables' clusters: one exact mode split among discrete copies)
  double floor = 1e-6;              // heavy: trace H above this fraction of trace(I_f − J_zh) ...
  double lambda_floor = 0.05;       // ... and λ above this (inside, the geostrophic accumulation)
};

struct VolumeSurvey {
  std::vector<VolumeMode> modes;      // λ > lambda_floor, heavy and settled, sorted by transverse weight descending
  std::vector<VolumeMode> unsettled;  // λ > lambda_floor, heavy, not settled when the budget ran out
  int shifts = 0;                     // shift-and-invert runs (one factorisation of Q(σ) each)
  Hermitian3 total = Hermitian3::Zero();        // Σ H over every node (= Gram(w))
  Hermitian3 geostrophic = Hermitian3::Zero();  // Σ H over |λ| <= lambda_floor
  std::vector<VolumeMode> rule;       // the plain rule's clusters, every λ of both signs: the measure as a whole, whose
                                      // band weights hold a dense cluster's light modes too (volume_table.cpp)
  int columns = 0;
};

// The plain rule first (A itself: an isolated mode such as an ellipsoid's spin-over settles in a few blocks); a heavy
// node that does not settle is then resolved by shift-and-invert block Lanczos on (A − σ)⁻¹ with σ just off it,
// whose rule settles nearest σ first. Each step solves the forced problem at σ: with y = (S − σ)⁻¹u,
//   (A − σ)⁻¹u = y + (S − σ)⁻¹ G p,   Q(σ) p = σ(σ² − 4) Gᵀ Ω y,   Q(σ) = σ² M + 2σ (iG) − 4 Kz
// (Gᵀ Ω (S − σ)⁻¹ G = −Q(σ)/(σ(σ² − 4)), volume_forms.hpp), Q(σ) in its real form factorised once per shift.
VolumeSurvey survey_volume_modes(const VolumeVelocity& V, const StiffnessSolver& M, const VolumeForms& forms,
                                 const VolumeSurveySettings& s);

}  // namespace rc::modes
