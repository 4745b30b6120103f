// How the results of either method (mesh or separable, cavity_table.hpp) become a mode table (docs/physics.md §4): the
// attributes and datasets both methods fill, filled in one place.
#pragma once

#include "cluster.hpp"
#include "convergence.hpp"
#include "meridian_mesh.hpp"
#include "mode_table.hpp"
#include "poincare_forms.hpp"

#include <vector>

namespace rc::modes {

// A table with the shape, its dimensions, m = 1, the frozen-fluid integrals, J_zh, sum_rule = A_f − J_zh and the
// normalisation of a and N².
ModeTable start_table(const geometry::ShapeSpec& shape, const FluidIntegrals& fluid, double J_zh);

// Appends the clusters as /modes rows (κ, λ, E, a = sqrt(E/2) with N² = 1, residual, spread, members) and sets the
// table's coverage Σ E / sum_rule.
void add_modes(ModeTable& table, const std::vector<Cluster>& clusters);

// /modes/dlambda, dE, converged (one per row, in row order) and the convergence attributes.
void add_convergence(ModeTable& table, const ConvergenceCheck& check, double tolerance);

// /bands.
void add_bands(ModeTable& table, const BandWeights& bands);

}  // namespace rc::modes
