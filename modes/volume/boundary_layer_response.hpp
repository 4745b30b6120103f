// The ideal liquid with Ekman layers on its walls: a 3-D cavity's forced response, filled or partially filled, at any
// small Ekman number on the ideal liquid's mesh (docs/volume.md §9). A 3-D mesh cannot resolve wall layers Ek^{1/2}
// thick at the Ekman numbers of real tanks (the viscous 3-D pencil stops near Ek = 1e-3 on this machine), so
// boundary-layer theory replaces the layers by what they do to the interior (Greenspan, "The Theory of Rotating
// Fluids", 1968, §2.6-2.8; docs/viscous.md §4 for one mode): the interior is inviscid, and on the wall
//   V·n = Ek^{1/2} ∇_s·(D U)        (Ekman pumping; n into the liquid, U the interior's slip along the wall),
//   (D U)± = U± / q±,  U± = U·e1 ± i U·e2 (e1 × e2 = n),  q± = (i(σ ± 2 ẑ·n))^{1/2} with Re q± > 0,
// while the layer's flux deficit −Ek^{1/2} D U carries moment. With V = L(σ)(u_k − ∇Π), L = i(iσ + 2ẑ×)⁻¹ and u_k the
// direction's Euler force, the weak continuity tested with the pressure space's q is
//   ∫ ∇q·L∇Π − Ek^{1/2} ∮_w ∇_s q·D[L∇Π]_t − (σ/b) ∫_Σ q Π
//       = ∫ ∇q·L u_k − Ek^{1/2} ∮_w ∇_s q·D[L u_k]_t − (i/b) ∫_Σ q ψ_k,
//   R_jk = ∫ u_j·V_k − Ek^{1/2} ∮_w u_j·D U_k − (i/b) ∫_Σ ψ_j Π_k,
// the viscous pencil's R_jk(σ) (viscous_volume_response.hpp) to first order in Ek^{1/2}: 3 × 3 about the centroid for
// a filled cavity, 5 × 5 over U_x, U_y, U_z, T̂_x, T̂_y about P0 for a partial fill (ψ the directions' surface
// potentials less their mean, b the free surface's radius: the kinematic and dynamic conditions of
// viscous_fill_surface.hpp; the free surface is stress-free and has no Ekman layer). At Ek = 0 it is the ideal
// liquid's resolvent. The line integral along a contact line, left out by the weak form, returns the layer's flux to
// the liquid there.
#pragma once

#include "volume_space.hpp"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct BoundaryLayerResponse {
  std::vector<Eigen::MatrixXcd> R;     // one per σ
  std::array<double, 3> origin{};      // the centroid (filled) or P0 (a partial fill), in the mesh's coordinates
  double surface_radius = 0;           // b; 0 for a filled cavity
  int unknowns = 0;                    // complex pressure unknowns
  std::size_t wall_points = 0;
  double seconds = 0;
};

// `space` pins a node for a filled cavity and none for a partial fill (VolumeSpace(mesh, 0, false)). Serial (one
// rank). Throws std::runtime_error with a one-line cause where σ is 0 or ±2 or the system is singular (an ideal
// eigenvalue at Ek = 0).
BoundaryLayerResponse boundary_layer_response(const VolumeSpace& space, double ekman,
                                              const std::vector<std::complex<double>>& sigmas,
                                              const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace rc::modes
