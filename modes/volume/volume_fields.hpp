// The fields of a 3-D table's rows (cavity-modes ellipsoid/volume --fields; docs/volume.md §5): for each row, its
// modes re-found as eigenpairs of the pressure pencil in a narrow window about the row's λ (SLEPc spectrum slicing,
// modes/ideal/qep_solver.hpp), and the row's field formed as the rotation field about u — the axis of the row's
// coupling tensor's largest eigenvalue — projected on them:
//   V = Σ_l V_l (c_lᴴ u) / ‖V_l‖²,  normalised to ∫|V|² = 1, its phase making a = uᴴc real and positive,
// so that a² = uᴴ H u when the window holds the row's modes (the check the command prints). P and V at the mesh
// nodes are complex amplitudes (ModeFields::dimension 3); a node's ∇P is the mean over the elements sharing it.
#pragma once

#include "mode_fields.hpp"
#include "mode_table.hpp"
#include "volume_forms.hpp"

#include <array>
#include <functional>
#include <string>

namespace rc::modes {

// `table` holds the rows (its /volume coupling tensors, λ, spread) computed on `space`. Throws std::runtime_error
// when the pencil has no eigenpair in a row's window.
ModeFields volume_mode_fields(const VolumeSpace& space, const VolumeForms& forms, const std::array<double, 3>& centroid,
                              const ModeTable& table, const std::function<void(const std::string&)>& progress = {});

// uᴴ H u for the row's largest eigenvalue (the a² its field should carry).
double largest_coupling(const ModeTable& table, std::size_t row);

}  // namespace rc::modes
