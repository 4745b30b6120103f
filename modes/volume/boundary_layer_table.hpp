// A response table of the ideal liquid with Ekman layers on its walls (docs/volume.md §9, "The table"), for chain-rom
// at Ekman numbers where no viscous mesh can be made. Its response is not a rational function (the layer's
// q± = (i(s ± 2ẑ·n))^{1/2} has a branch point at every critical latitude), so it is not fitted over a window: the
// table is the ideal liquid's rows (its survey, each row also at −λ) and its λ = 0 weight as a row spinning up at the
// rate Ek^{1/2}, plus one correction dipole per frequency of --exact-at, poles p_e = Re s_e + i w and p_e + i w with
// residues C_e and −C_e (each with its mirror), and a second one twice as wide, whose residues make the table's R and
// its slope equal the boundary-layer response's there (boundary_layer_response.hpp; the slope by a step 1e-4), to
// rounding, and whose tails fall off as 1/|s − p_e|² away from it:
//   R(s) = Σ_rows [H/(s − λ) + conj(H)/(s + conj(λ))] + Σ_e [C_e (1/(s − p_e) − 1/(s − p_e − iw)) + mirror].
// A chain's root at an exact-at frequency is then the root of its characteristic equation with the boundary-layer
// response; remade exact at the root it gives, the table settles it in one or two rounds (the slope is matched too).
// Roots elsewhere hold the damped ideal rows and the corrections' tails.
#pragma once

#include "mode_table.hpp"
#include "volume_mesh.hpp"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rc::modes {

struct BoundaryLayerTableRequest {
  geometry::VolumeShapeSpec shape;
  geometry::MeshOptions mesh;                  // the ideal liquid's mesh (the ideal table's)
  double ekman = 0;                            // > 0
  std::vector<std::complex<double>> exact_at;  // tank frequencies, at least one (s and −s̄ are one)
  double lo = 0, hi = 0;                       // the window the table is named for (its fit_lo, fit_hi)
  double width = 0.05;                         // w, the correction poles' distance from the real axis
};

struct BoundaryLayerTableResult {
  ModeTable table;
  std::vector<std::complex<double>> exact_at;  // as used: Re s ≥ 0, each once
  double exact_error = 0;  // the table's R against the boundary-layer response at them, relative to its largest entry
  double correction = 0;   // the largest |C_e| relative to the largest |R| there: how far the ideal rows were off
  int unknowns = 0;
  double seconds = 0;
};

// `ideal`: the ideal 3-D table of the same tank made on the same mesh (its rows and tensors). Serial. Throws
// std::runtime_error with a one-line cause.
BoundaryLayerTableResult boundary_layer_table(const ModeTable& ideal, const BoundaryLayerTableRequest& request);

}  // namespace rc::modes
