// Human-readable and JSON views of a mode table (`cavity-modes info`, docs/physics.md §4).
#pragma once

#include "mode_table.hpp"

#include <string>

namespace rc::modes {

std::string table_text(const ModeTable& table);
// One plain line when some clusters did not converge: which quantities of this table did, and where to read
// more (docs/trust.md). Empty when every cluster converged or the table was not checked.
std::string convergence_note(const ModeTable& table);
// One JSON object: every root attribute, plus "modes": {"kappa": [...], "lambda": [...], ...}.
std::string table_json(const ModeTable& table);

}  // namespace rc::modes
