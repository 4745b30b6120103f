// Human-readable and JSON views of a mode table (`cavity-modes info`, docs/physics.md §4).
#pragma once

#include "mode_table.hpp"

#include <string>

namespace rc::modes {

std::string table_text(const ModeTable& table);
// One JSON object: every root attribute, plus "modes": {"kappa": [...], "lambda": [...], ...}.
std::string table_json(const ModeTable& table);

}  // namespace rc::modes
