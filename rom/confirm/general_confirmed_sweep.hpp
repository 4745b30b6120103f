// A sweep of a chain without axial symmetry whose viscous tanks are response tables, 3-D or axisymmetric Krylov ones
// (docs/rom.md, "Spin sweeps of chains without axial symmetry"): the roots at each point confirmed with the fluid's
// own response, by remade tables.
// A key that moves a viscous tank's Ekman number (body[k].spin, system.spin_factor, a cavity's scale) makes each such
// table again at the point's Ek from its recorded command line; `sweep --confirm` with any other key starts each
// point from a copy of the scene's table. Then the point's tables are remade exact at its roots until they stop
// moving (general_confirmation.hpp). The scene's own table files are never touched.
#pragma once

#include "confirmed_sweep.hpp"
#include "scene.hpp"
#include "sweep.hpp"
#include "table_refinement.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

// Runs the sweep point by point (each point's cavity-modes runs are the work); one line per point to `log`. A point
// whose tables cannot be made is reported in its row (not evaluated); a scene whose tables cannot be remade at all
// (neither 3-D nor axisymmetric Krylov response tables, no recorded command line) throws SceneError. At two spins each
// point is confirmed as confirm_general does (driven_frequencies.hpp).
std::vector<ConfirmedSweepPoint> run_general_confirmed_sweep(const Scene& base, const SweepAxis& axis,
                                                             const std::string& cavity_modes, double tolerance,
                                                             const ProgramRunner& run, std::ostream& log);

}  // namespace rc::rom
