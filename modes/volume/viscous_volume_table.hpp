// A 3-D cavity's viscous mode table (docs/volume.md §7, "The viscous table"): the damped modes as its rows, each with
// λ + i·decay and its coupling tensor H = (fᵀx)(fᵀy)ᵀ (not Hermitian: x, y the right and left eigenvectors), and the
// cavity's tensors — the frozen fluid's inertia, Zhukovsky's inertia, the tensor sum rule and the λ = 0 weight — from
// the ideal table of the same cavity (they are the Ek → 0 limits the rows' couplings are measured against).
#pragma once

#include "mode_table.hpp"
#include "viscous_volume_run.hpp"

namespace rc::modes {

// `ideal`: the ideal 3-D table of the same cavity (cavity-modes ellipsoid / volume without --ekman). Throws
// std::runtime_error when two targets found the same damped mode (it would be counted twice) or the table breaks one
// of its identities (ModeTable::validate).
ModeTable viscous_volume_table(const ModeTable& ideal, const ViscousVolumeRequest& request,
                               const ViscousVolumeResult& result);

}  // namespace rc::modes
