// A partially filled 3-D tank's mode table for chain-rom (docs/volume.md §8, "The table"): /volume with the frozen
// liquid about its centroid and the rotation couplings about P0 (the spin axis's point at the centroid's height), and
// /volume_free_surface with the five directions' couplings that place the body's joint anywhere on the spin axis.
#pragma once

#include "free_surface_run.hpp"
#include "mode_table.hpp"

namespace rc::modes {

// The settled rows only (the survey's `modes`; its unsettled weight is reported by the command, not tabled).
ModeTable free_surface_table(const FreeSurfaceRunResult& r, const geometry::VolumeShapeSpec& shape,
                             const FreeSurfaceSurveySettings& settings);

}  // namespace rc::modes
