// Shift-and-invert Gauss rules of the coupling's spectral measure: where the plain survey
// (spectral_survey.hpp) resolves the extremes of the spectrum first, a Lanczos process on (A − σ)⁻¹
// resolves the part of μ = Σ E_l δ(λ − λ_l) nearest the shift σ first. A node of its rule that has stopped
// moving IS a cluster (docs/physics.md §2): its λ is the eigenvalue and its weight the E summed over the discrete
// eigenpairs it stands for — eigenpairs closer together than the Krylov space can tell apart, which is
// exactly the splitting of one exact mode among several discrete copies.
//
// Each step solves the forced problem at frequency σ: with y = (S − σ)⁻¹u (pointwise),
//   v = (A − σ)⁻¹ u = y + (S − σ)⁻¹ G p,   Gᵀ Ω (S − σ)⁻¹ G p = −Gᵀ Ω y,
// and Gᵀ Ω (S − σ)⁻¹ G = −Q(σ) / (σ (σ² − 4)) with Q(σ) = σ² M + 2σ Gc − 4 Kz the QEP of docs/physics.md §2 (m = 1),
// factorised once per shift (MUMPS LDLᵀ; Q(σ) is indefinite). A node θ maps back to λ = σ + 1/θ.
#pragma once

#include "lanczos.hpp"
#include "poincare_forms.hpp"
#include "velocity_space.hpp"

#include <vector>

namespace rc::modes {

struct ShiftInvertSettings {
  int max_steps = 150;              // Lanczos steps per shift (at most)
  int min_steps = 10;
  int check_every = 5;              // compare the rule every this many steps
  double lambda_tolerance = 1e-11;  // settled: λ moved less than this · max(|λ|, 0.1) ...
  double weight_tolerance = 1e-9;   // ... and the weight less than this (relative) between two checks
  double merge_width = 1e-5;        // nodes closer than this · max(|λ|, 0.1) are compared (and returned) as one:
                                    // a Krylov space that keeps splitting one cluster into near-copies moves
                                    // its nodes, but not their sum
};

struct SettledNode {
  double lambda = 0, E = 0;
  double dlambda = 0, dE = 0;  // last observed change (absolute λ, relative E)
  double residual = 0;         // bound on ‖(A − λ)y‖ for the node's Ritz vector y (‖y‖ = 1)
};

struct ShiftInvertRule {
  std::vector<SettledNode> settled;    // in the window, heavier than the floor, stopped moving
  std::vector<SettledNode> unsettled;  // in the window, heavier than the floor, still moving at the step limit
  int steps = 0;
};

class ShiftInvertSurvey {
 public:
  // w: the solenoidal coupling vector P_H(e1 × r); mass = π‖w‖² = A_f − J_zh.
  ShiftInvertSurvey(const VelocitySpace& V, const PoincareForms& forms, const Eigen::VectorXd& w, double mass);

  // Runs the Lanczos process on (A − σ)⁻¹ until every node with λ in [lo, hi] and weight >= floor
  // (absolute) has settled, or the step limit. Throws if Q(σ) cannot be factorised.
  ShiftInvertRule run(double sigma, double lo, double hi, double floor, const ShiftInvertSettings& settings) const;

 private:
  const VelocitySpace& V_;
  const PoincareForms& forms_;
  Eigen::VectorXd w_;
  double mass_;
};

}  // namespace rc::modes
