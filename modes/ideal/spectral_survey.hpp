// Spectral survey: the Gauss quadrature of the coupling's spectral measure μ = Σ_l E_l δ(λ − λ_l)
// (docs/physics.md §2), computed by a Lanczos process started from the coupling vector.
//
// Why: the discrete spectrum fills (−2, 2) densely (about 2·ndof eigenvalues), but E sits on a few of
// them. The k-point Gauss rule of μ locates where E sits at the cost of k Lanczos steps, with no
// eigen-solve; its rule bounds where the clusters can be, and shift-and-invert rules resolve them
// (cluster_search.hpp).
//
// How: the discrete QEP is the eigenproblem of the self-adjoint operator A = P_H S on the discretely
// solenoidal fields H_h = {V : Gᵀ Ω V = 0} of the quadrature-point velocity space (V = (i a, b, i c)
// e^{iφ}, stored as real (a, b, c) at each quadrature point, with inner product Σ ω (a a' + b b' + c c'),
// ω = w r). Here S(a, b, c) = (−2b, −2a, 0) is the Coriolis term 2iẑ×, G p = (p_r, −p/r, p_z) the
// gradient of an m = 1 pressure and P_H = I − G M⁻¹ Gᵀ Ω the projection (M = Gᵀ Ω G = Kh + Kz).
// The coupling vector is W = e1 × r = (z', −z', −r); μ has total mass π‖P_H W‖² = A_f − J_zh.
#pragma once

#include "fe_space.hpp"
#include "lanczos.hpp"
#include "stiffness_solver.hpp"
#include "velocity_space.hpp"

#include <vector>

namespace rc::modes {

struct SurveySettings {
  int max_steps = 200;          // Lanczos steps (nodes of the Gauss rule)
  double tolerance = 5e-4;      // stop when the heavy nodes move less than this (relative): the rule only
                                // bounds the windows of the cluster search and gives the band weights
  double weight_floor = 1e-3;   // "heavy": weight above this fraction of A_f − J_zh ...
  double lambda_floor = 0.05;   // ... and |λ| above this: nodes inside the λ ≈ 0 accumulation keep moving
                                // as the rule grows and are not refined anyway
};

struct SpectralSurvey {
  std::vector<GaussNode> nodes;  // sorted by λ
  int steps = 0;
  bool exhausted = false;        // the Krylov space became invariant: the rule is exact
};

// v <- P_H v = v − G M⁻¹ Gᵀ Ω v (`solver` factorises M).
void project_solenoidal(const VelocitySpace& V, const StiffnessSolver& solver, Eigen::VectorXd& v);

// w: the solenoidal coupling vector P_H(e1 × r) (its measure has mass π‖w‖² = A_f − J_zh).
SpectralSurvey survey_spectral_measure(const VelocitySpace& V, const StiffnessSolver& solver, const Eigen::VectorXd& w,
                                       const SurveySettings& settings);

}  // namespace rc::modes
