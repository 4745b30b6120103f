// A 3-D tank (a table of cavity-modes ellipsoid / volume: docs/volume.md §5) in a body of the general chain
// (docs/rom.md, "Bodies and tanks without axial symmetry"): its frozen fluid as a 3 × 3 inertia tensor about the body's
// joint O_k, the geostrophic (λ = 0) weight, and each kept mode as a frequency with a complex coupling vector.
#pragma once

#include "mode_table.hpp"
#include "scene.hpp"

#include <Eigen/Dense>

#include <vector>

namespace rc::rom {

// One fluid mode of the general chain: the flow z V e^{iλt} in its body's frame (its conjugate at −λ is the same real
// motion), forced by the body's angular acceleration and moving the body through its angular momentum
// (docs/rom.md, "Bodies and tanks without axial symmetry"):
//   ż = iλ z − c̄·δω̇,   h = 2 Re(z c)   (c_j = ρ∫(e_j × r)·V, ρ∫|V|² = 1, so that H = c cᴴ in kg m²).
struct GeneralMode {
  int body = 0;             // 0-based body index
  int table_row = 0;        // the table's row it comes from
  double lambda = 0;        // rad/s: ω_k0 λ_table (Kononov (21))
  Eigen::Vector3cd c;       // kg^{1/2} m
};

struct VolumeTank {
  double mass = 0;          // kg
  double center = 0;        // O_k -> the fluid's centroid along the body's axis (m)
  Eigen::Matrix3d inertia;  // the frozen fluid's inertia tensor about O_k (kg m²), body axes
  Eigen::Matrix3d geostrophic;  // the λ = 0 weight (kg m², real symmetric): fluid that does not follow the body
  std::vector<GeneralMode> modes;
  double coverage = 0;      // trace of the kept H (both signs of λ) and the geostrophic over that of the sum rule
};

// Body k's tank from its 3-D table: the rows kept as an axisymmetric tank's are (every coupling one, or the first
// `modes`, or those reaching `coverage` of the sum rule's trace), each row's H split into rank-one couplings (a row
// sums a cluster of discrete copies: H = Σ c cᴴ). Throws SceneError naming the key for what the general chain does not
// take (a viscous tank, the static correction, a Galerkin reduction, a companion, a centroid off the axis).
VolumeTank volume_tank(const Scene& scene, int k, const rc::ModeTable& t);

}  // namespace rc::rom
