// The fields of a viscous table's damped modes at the mesh nodes (cavity-modes --ekman --fields; docs/viscous.md,
// "Fields"). A damped mode is complex: the physical velocity is Re[(V_r, V_φ, V_z) e^{iφ + iλt}] with complex
// amplitudes, stored as V (real parts) and V_imag (imaginary parts), and likewise the pressure P as p and p_imag.
// From the Taylor–Hood unknowns (taylor_hood_space.hpp): V_r = (u+ + u−)/2, V_φ = (u+ − u−)/(2i), V_z = u_z,
// P = −iQ; the pressure of order k − 1 is evaluated at the velocity nodes. The mode is normalised as the table's
// (xᵀ𝓜x = 1, a ≥ 0 in real part), and energy_density = |V|² r / (2π x̄ᵀ𝓜x), so that 2π ∫∫ it dr dz = 1 as for the
// ideal fields: it shows where the mode's kinetic energy sits — the Ekman layers on the wall and the shear
// layers in the interior.
#pragma once

#include "mode_fields.hpp"
#include "taylor_hood_space.hpp"
#include "viscous_eigensolver.hpp"

namespace rc::modes {

// The mesh part of /fields (points, sub-triangles, FE triangles) for the space's mesh.
ModeFields viscous_fields_mesh(const TaylorHoodSpace& space);

// One mode's field; `mode.vector` must hold the eigenvector (ViscousSolveSettings::keep_vector) on this rank.
ModeFields::Mode viscous_mode_field(const TaylorHoodSpace& space, const ViscousMode& mode);

}  // namespace rc::modes
