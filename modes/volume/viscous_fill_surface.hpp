// The free surface of a partially filled 3-D tank in the viscous pencil (docs/volume.md §8, "The viscous liquid's
// pencil"): the surface ρ = b about the craft's spin axis is stress-free, and its displacement η outwards from the axis
// enters as unknowns η̃ = iη (one per velocity node of the surface off the walls: no-slip pins the contact line, η = 0
// there, as the meridian solver does, viscous_forms.hpp). With S = ∫_Σ ζ (V·e_ρ) dS and M_s = ∫_Σ ζ η dS, the
// pencil of viscous_volume_forms.hpp becomes
//   A = [[i (C + Ek K_s), Bᵀ, b Sᵀ], [B, 0, 0], [b S, 0, 0]],   𝓜 = diag(M, 0, b M_s),
// so that x̄ᵀ𝓜x = ∫|V|² + b∫_Σ|η|² is §8's energy (the normal stress balances the base pressure's jump, −bη; the
// kinematic condition is iλη = V·e_ρ).
//
// Its forcing directions are §8's five, about P0 (the spin axis's point at the liquid's centroid's height):
// U_k = (e_k × r, (χ_k − χ̄_k)/b) for k = x, y, z (χ_x = xz, χ_y = yz, χ_z = −(x² + y²), r from P0) and
// T̂_k = (e_k × ẑ, (r_k − r̄_k)/b) for k = x, y. The body's rotation Ω_k drives the liquid as (σ𝓜 − A) x = −σ Ω_k F_k
// and the liquid's moment is G_jᵀx, with
//   F_k = (∫ W·u_k, +i ∫_Σ ζ ψ_k dS),   G_k = F̄_k   (u_k, ψ_k the direction's velocity and surface parts, ψ times b):
// the surface's centrifugal forcing, moved into the displacement (η' = η − Ω_k ψ_k/b), enters the kinematic row,
// and η = −iη̃ makes the surface's share of the moment ∫ ψ_j η imaginary in η̃ (docs/volume.md §8).
#pragma once

#include "block_pencil.hpp"
#include "volume_free_surface.hpp"
#include "volume_taylor_hood.hpp"

#include <array>
#include <complex>
#include <vector>

namespace rc::modes {

struct ViscousFillSurface {
  VolumeFreeSurface surface;        // the faces on ρ = b and their quadrature (dof = mesh node: no pinned node)
  std::array<std::vector<int>, 3> velocity;  // per mesh node, its V_x, V_y, V_z unknowns (−1 on the walls)
  std::vector<int> eta;             // per surface index, its η̃ unknown (−1 on the contact line)
  int first = 0, count = 0;         // η̃ unknowns first … first + count − 1
  std::array<double, 3> axis_point{};  // P0
};

// Numbers the η̃ unknowns from `first` (the space's size). `centroid`: the liquid's (P0 takes its height).
ViscousFillSurface number_fill_surface(const VolumeTaylorHoodSpace& space, const std::array<double, 3>& centroid,
                                       int first);

// The surface's terms of Re A (b S and b Sᵀ) and 𝓜 (b M_s).
void add_fill_surface_terms(const ViscousFillSurface& s, Triplets& ar, Triplets& mass);

// The five directions' input functionals F_0 … F_4 (U_x, U_y, U_z, T̂_x, T̂_y) over the complex problem's n unknowns,
// from the whole mesh's rotation functionals about the liquid's centroid c (∫ W·(e_k × (x − c))) and translation
// functionals (∫ W·e_k): about P0, e_k × (x − P0) = e_k × (x − c) + e_k × (c − P0), and T̂_x, T̂_y move the liquid as
// −e_y, e_x. Then the surface parts.
constexpr int kFillDirections = 5;
using DirectionFunctionals = std::array<std::vector<double>, 3>;
std::array<std::vector<std::complex<double>>, kFillDirections> fill_inputs(const ViscousFillSurface& s,
                                                                         const DirectionFunctionals& rotations,
                                                                         const DirectionFunctionals& translations,
                                                                         const std::array<double, 3>& centroid);

}  // namespace rc::modes
