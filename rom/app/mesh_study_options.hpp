// The mesh study's options (docs/rom.md, "Mesh error of confirmed roots"), one registration for every command that
// confirms roots by forced solves: confirm, spectrum --confirm, sweep --confirm and the sweeps over spin.
#pragma once

#include "mesh_study.hpp"

#include <CLI/CLI.hpp>

namespace rc::rom::app {

// --refine, --refine-by, --mesh-size, --order, --mesh-tolerance into `study`; `when` prefixes each description
// ("with --confirm: ").
void add_mesh_study_options(CLI::App* cmd, MeshStudy& study, const std::string& when = "");

}  // namespace rc::rom::app
