// The fields of a partially filled tank's table (cavity-modes --fill --fields; docs/modes.md, "Fields"). Each row of
// the mesh method's table is one eigenpair, stored normalised like the table: the state (V, η) with
// ‖W‖² = ∫|V|² dτ + b ∫|η|² dS = 1 and a ≥ 0 (free_surface_coupling.hpp). V comes from p as for a filled cavity
// (cluster_fields.hpp); the free surface's outward displacement is η = −p/b on r = b (the dynamic condition: the
// scaled field's η̃ = −λDp/b with Ṽ = λDV), so the stored p on the free surface shows the surface's shape.
#pragma once

#include "fe_space.hpp"
#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "partial_fill_spectrum.hpp"

namespace rc::modes {

// `s` must have been solved on `space` with keep_pressure (free_surface_mesh.hpp). Throws std::runtime_error if a
// row's λ is not one of the spectrum's pairs.
ModeFields free_surface_fields(const FESpace& space, const PartialFillSpectrum& s, const ModeTable& table);

}  // namespace rc::modes
