// The modes of a partially filled 3-D tank that couple to the body (docs/volume.md §8): a block Lanczos Gauss rule of
// the five forcing directions' matrix-valued spectral measure under the free-surface operator (free_surface_dynamics.hpp)
// — rotation about x, y, z about the spin axis's point P0 at the centroid's height, and the two offsets T̂_x, T̂_y that
// move that point along the axis. A mode W_l (‖W_l‖ = 1) has the coupling c_l = ⟨direction_j, W_l⟩ and the Hermitian
// weight H_l = c_l c_lᴴ; over every mode of both signs of λ, Σ H_l = Gram(U, T̂) (the sum rule: for the rotations
// I_f − J_D + K, the frozen liquid's inertia less Zhukovsky's with the surface at zero potential plus the surface's
// re-centring inertia, docs/physics.md §2).
#pragma once

#include "free_surface_dynamics.hpp"

#include <Eigen/Core>

#include <complex>
#include <vector>

namespace rc::modes {

using Hermitian5 = Eigen::Matrix<std::complex<double>, 5, 5>;

struct FreeSurfaceMode {
  double lambda = 0;
  Hermitian5 H = Hermitian5::Zero();  // Σ c cᴴ over the cluster's Ritz values
  double spread = 0;                  // weight-weighted spread of λ in the cluster
  int members = 0;
  double residual = 0;                // bound on the distance from λ to the discrete eigenvalue (largest member's)
  // The transverse rotation weight H_xx + H_yy: for a tank on the axis the meridian table's E.
  double transverse() const { return (H(0, 0) + H(1, 1)).real(); }
};

struct FreeSurfaceSurveySettings {
  int plain_columns = 120;           // the plain rule (A itself): locates the heavy weight
  int shift_columns = 240;           // at most, each shift-and-invert run on (A − σ)⁻¹, σ just off a heavy plain node
  int max_shifts = 8;
  double merge_width = 1e-5;         // Ritz values closer than this · max(|λ|, 0.1) form one cluster
  double residual_tolerance = 1e-6;  // a cluster is a mode when its λ bound is below this · max(|λ|, 0.1)
  double floor = 1e-3;               // heavy: its trace above this fraction of the Gram matrix's
  double lambda_floor = 0.05;        // and λ above this (inside, the geostrophic accumulation)
  double window = 0.05;              // a shift keeps the modes within this · max(|σ|, 0.1) of σ
};

struct FreeSurfaceSurvey {
  std::vector<FreeSurfaceMode> modes;      // λ > 0, heavy and settled, by transverse weight descending
  std::vector<FreeSurfaceMode> unsettled;  // λ > 0, heavy, residual above the tolerance
  std::vector<FreeSurfaceMode> rule;       // every cluster of the plain rule, both signs of λ
  Hermitian5 gram = Hermitian5::Zero();    // of the five directions
  Eigen::Matrix<double, 5, 5> surface_gram = Eigen::Matrix<double, 5, 5>::Zero();  // their η parts': b ∫ η_i η_j dS (K)
  Hermitian5 total = Hermitian5::Zero();   // Σ H over the plain rule (= gram: the Gauss rule's exactness)
  int columns = 0;                         // of the plain rule
  int shifts = 0;
};

FreeSurfaceSurvey survey_free_surface_modes(const FreeSurfaceDynamics& A, const FreeSurfaceSurveySettings& s = {});

}  // namespace rc::modes
