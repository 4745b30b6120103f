// Provenance of a table: which geometry and which command made it (/provenance, docs/physics.md §4), so that a
// table found months later can be made again and compared with its refinement.
#pragma once

#include "meridian_mesh.hpp"
#include "mode_table.hpp"

#include <string>
#include <vector>

namespace rc::modes {

// The command line as a shell would take it back (arguments with spaces or quotes single-quoted).
std::string quoted_command_line(const std::vector<std::string>& argv);

// Fills table.geometry_source ("cylinder height=2 radius=1", or the section file's path), table.geometry_text (the
// section file's full text; a binary file is described, not stored) and table.command_line.
void record_provenance(ModeTable& table, const geometry::ShapeSpec& shape, const std::string& command_line);

}  // namespace rc::modes
