// The pairs of a partially filled tank's free-surface quadratic (free_surface_quadratic.hpp) nearest given
// frequencies, by SLEPc's PEP: TOAR with shift-and-invert at each target, a sparse LU of the quadratic there (MUMPS).
// For meshes beyond the dense solver's reach (free_surface_mesh.hpp): not complete, so its Σ E is only what the pairs
// found hold, and a table made with it says how much of the sum rule A_f + K2 − J_D its rows cover.
#pragma once

#include "fe_space.hpp"
#include "partial_fill_spectrum.hpp"

#include <vector>

namespace rc::modes {

// The unknowns of the quadratic on this mesh: pressure dofs and one per free-surface dof.
long free_surface_unknowns(const FESpace& space);

// Up to `per_target` pairs nearest each target (fewer where SLEPc converged fewer: counted in short_targets) (real frequencies, ω0 = 1), pairs found from two targets kept once,
// sorted by E descending. Throws std::runtime_error when SLEPc fails or does not converge, or returns an eigenvalue
// with |Im λ| above 1e-4 max(1, |λ|) (the problem is self-adjoint with positive energy); below it, a near-double real
// eigenvalue split by rounding, counted in `skipped` and not kept. With keep_pressure each pair keeps its eigenvector.
PartialFillSpectrum solve_partially_filled_near(const FESpace& space, const std::vector<double>& targets,
                                                int per_target, bool keep_pressure = false);

}  // namespace rc::modes
