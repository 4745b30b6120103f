// A response table of the fluid in a full sphere or a spherical shell by the spectral method: R(s) by the spectral
// forced solves of shell_response.hpp, fitted on a window as the finite elements' response-fit tables are
// (viscous/window_fit.hpp), checked against the same solves at a coarser truncation, and written as a viscous table
// (format version 2, pseudo-modes) that chain-rom reads like any response-fit table (docs/spherical.md, "Response
// tables for chain-rom"). Under mpirun the frequencies are shared out between the ranks.
#pragma once

#include "mode_table.hpp"
#include "shell_pencil.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rc::modes::spherical {

struct ShellTableRequest {
  ShellSettings fine;            // the table's truncation
  ShellSettings check;           // a coarser one: R's change against it on the window is the table's truncation error
  std::vector<double> window;    // increasing real frequencies, at least 9
  double max_fit_error = 1e-6;   // relative to max |R| on the window
};

struct ShellTable {
  ModeTable table;
  double truncation_change = 0;  // max of |R_fine − R_check| / max |R_fine| over every 4th window sample
};

// The frozen fluid's integrals in closed form (ρ = 1, outer radius 1): volume (4π/3)(1 − r_i³), A_f = C_f =
// (8π/15)(1 − r_i⁵), centroid 0, and J_zh = 0 (turning a sphere about a diameter moves no ideal fluid: the
// potential of the rigid rotation's normal velocity, zero on a sphere, vanishes).
ModeTable shell_table_start(const ShellSettings& settings);

// Throws std::invalid_argument for a window of fewer than 9 or unsorted frequencies, std::runtime_error (one line)
// when the fit's error stays above max_fit_error or a factorisation fails. `note` receives progress lines.
ShellTable shell_response_table(const ShellTableRequest& request, const std::function<void(const std::string&)>& note);

}  // namespace rc::modes::spherical
