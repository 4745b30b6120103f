// A partially filled 3-D tank under rapid spin (docs/volume.md §8): the centrifugal acceleration about the craft's
// spin axis — parallel to z, through a point that need not lie in the tank — presses the liquid outwards, so the
// liquid at rest fills the part of the cavity beyond the cylinder ρ = b about that axis (ρ the distance from it),
// and the free surface is that cylinder's piece inside the cavity. b follows from the fill: the volume beyond the
// cylinder is the fill times the cavity's.
#pragma once

#include <array>

namespace rc::geometry {

struct LiquidCut {
  int tag = -1;        // the liquid's OpenCASCADE volume
  double radius = 0;   // b
};

// Cuts the OpenCASCADE volume `tag` (synchronised model) to its liquid at fill in (0, 1); the cavity volume is
// replaced by the liquid's. Throws std::runtime_error when the fill is outside (0, 1) or OpenCASCADE's cut fails.
LiquidCut cut_to_fill(int tag, double fill, const std::array<double, 2>& spin_axis);

// True when the point lies on the free surface ρ = b about the axis (to `tolerance`, relative to max(1, b)). gmsh's
// nodes on OpenCASCADE's cut cylinder lie off ρ = b by up to 2.1e-6 (a half-full sphere two radii off the axis,
// 2026-12-07; 1e-15 for other placements of the same tank), which a tolerance of 1e-7 took for a wall and lost 37 %
// of the surface's area; the wall's nodes next to the contact line lie O(h) off it.
bool on_free_surface(const std::array<double, 3>& x, double radius, const std::array<double, 2>& spin_axis,
                     double tolerance = 2e-5);

}  // namespace rc::geometry
