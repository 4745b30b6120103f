// The viscous fluid's forced response in a 3-D cavity, no modes (docs/volume.md §7, "The forced response"): the
// fluid's moment about e_j per unit rotation about e_k at the complex frequency σ (e^{iσt} in the turning frame),
//   R_jk(σ) = f_jᵀ (σ𝓜 − A)⁻¹ f_k = Σ_l H^l_jk / (σ − λ_l) + (a constant from the pencil's infinite eigenvalues),
// with A, 𝓜, f_k of viscous_volume_forms.hpp and H^l the damped modes' coupling tensors (viscous_volume_modes.hpp),
// the sum over every mode of both signs of Re λ. For an axisymmetric cavity ½ (R_xx + i R_xy − i R_yx + R_yy) is the
// meridian solver's R(σ) (docs/viscous.md, "Response function"): the m = 1 part. One MUMPS factorisation of σ𝓜 − A
// per σ (viscous/shifted_solver.hpp: the ordering kept across σ), three solves on it.
#pragma once

#include "viscous_volume_run.hpp"

#include <Eigen/Core>

#include <array>

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct ViscousVolumeResponseRequest {
  geometry::VolumeShapeSpec shape;
  geometry::MeshOptions mesh;  // as for the damped modes (viscous_volume_run.hpp), resolved by the command
  double ekman = 0;            // > 0
  std::vector<std::complex<double>> sigmas;
};

struct ViscousVolumeResponse {
  std::vector<Eigen::Matrix3cd> R;  // one per σ, in the spin frame about the centroid
  int unknowns = 0;
  std::size_t elements = 0;
  double mesh_h = 0, seconds = 0;
};

// Throws std::runtime_error with a one-line cause (a bad mesh, a σ on which the factorisation fails). Collective on
// PETSC_COMM_WORLD; `progress` gets a line per phase and one per σ.
ViscousVolumeResponse viscous_volume_response(const ViscousVolumeResponseRequest& request,
                                              const std::function<void(const std::string&)>& progress = {});

// A partially filled tank's 5 × 5 response about P0 (docs/volume.md §8, "The viscous liquid's pencil"):
//   R_jk(σ) = G_jᵀ (σ𝓜 − A)⁻¹ F_k over the directions U_x, U_y, U_z, T̂_x, T̂_y (viscous_fill_surface.hpp);
// the rotation about the axis's point O = P0 − c ẑ is U_k + c T̂_k, so R about O is B R Bᵀ, B = [I₃ | c (e_x, e_y)].
using FillResponse = Eigen::Matrix<std::complex<double>, 5, 5>;
std::vector<FillResponse> forced_fill_response(const ViscousVolumeForms& forms,
                                               const std::vector<std::complex<double>>& sigmas,
                                               const std::function<void(std::size_t)>& done = {});

// The partially filled tank's (request.shape.fill < 1) response at every σ: meshes, assembles, solves.
struct ViscousFillResponse {
  std::vector<FillResponse> R;          // about P0, over U_x, U_y, U_z, T̂_x, T̂_y
  std::array<double, 3> axis_point{};   // P0, in the tank's coordinates
  double surface_radius = 0;            // b
  int unknowns = 0, surface_unknowns = 0;
  std::size_t elements = 0;
  double mesh_h = 0, seconds = 0;
};
ViscousFillResponse viscous_fill_response(const ViscousVolumeResponseRequest& request,
                                          const std::function<void(const std::string&)>& progress = {});

// The 3 × 3 response at each σ of an assembled system (the same definition).
std::vector<Eigen::Matrix3cd> forced_volume_response(const ViscousVolumeForms& forms,
                                                     const std::vector<std::complex<double>>& sigmas,
                                                     const std::function<void(std::size_t)>& done = {});

}  // namespace rc::modes
