// `cavity-modes response SHAPE --ekman Ek --sigma FROM:TO:N --galerkin -o FILE.h5`: the viscous fluid reduced by a
// Galerkin projection on its forced solutions at the window's samples and beyond it (viscous/galerkin_response.hpp;
// docs/viscous.md, "Galerkin response table"). The table's rows are the reduced pencil's Ritz pairs (pseudo-modes
// with the Galerkin residues), its /galerkin block their Gram and viscous matrices and couplings: a table chain-rom
// reads like a response fit, whose fluid also holds an energy (reduction = "galerkin").
#pragma once

#include "cavity_response.hpp"
#include "mode_table.hpp"

namespace rc::modes {

// Throws std::runtime_error with a one-line cause: a bad window (check_response_window), a failed solve, or an error
// between the samples (measured against forced solves at their midpoints) above `max_error`.
ModeTable galerkin_response_table(const ResponseRequest& request, double max_error);

// The same kind of table from a rational Krylov space with greedily chosen expansion points
// (viscous/krylov_response.hpp; docs/viscous.md, "Krylov response table"): a few factorisations and many
// back-substitutions instead of a forced solve per sample, to `max_error` of max|R| and `max_decay_error` of Im R
// itself on the window (krylov_response.hpp). Throws std::runtime_error with a one-line cause.
ModeTable krylov_response_table(const ResponseRequest& request, double max_error, double max_decay_error);

}  // namespace rc::modes
