// Writers of chain-rom's results: time histories (HDF5 or CSV) and the spectrum (text / JSON).
// Files are written to a temporary name beside the target and renamed into place, so a failure
// never leaves a partial file.
#pragma once

#include "chain_model.hpp"
#include "general_run.hpp"
#include "nonlinear_run.hpp"
#include "propagation.hpp"
#include "spectrum.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace rc::rom {

// HDF5 unless the name ends in .csv. Layout in docs/rom.md ("output").
void write_history(const ChainModel& m, const History& h, const std::filesystem::path& out);
// The nonlinear model's history of n bodies: the same layout plus quaternion (4n per sample), spin (n) and
// angular_momentum (3); attribute model = "nonlinear". docs/rom.md, "Nonlinear chain".
void write_nonlinear_history(const NonlinearHistory& h, int n, const std::filesystem::path& out);

// The chain without axial symmetry's history (general_run.hpp): t, u (in space), z (its modes' amplitudes), spin when
// its spins' rates are coordinates; attribute model = "general". HDF5 unless the name ends in .csv.
void write_general_history(const GeneralChain& g, const GeneralHistory& h, const std::filesystem::path& out);

// docs/physics.md §4: {"roots": [[re, im], ...], "stable": bool, "margin": float, "det_residual": float}
std::string spectrum_json(const ChainModel& m, const Spectrum& sp);
// The bodies' lines, the roots (without `all`: the bodies' roots, the growing ones and those a check marks, then one
// line on the rest), the verdict and the checks.
void print_spectrum(std::ostream& os, const ChainModel& m, const Spectrum& sp, bool all = false);
void print_roots(std::ostream& os, const ChainModel& m, const Spectrum& sp, bool all);
void print_outside_fit(std::ostream& os, const ChainModel& m, const Spectrum& sp);
// The verdict of a chain with friction or viscous tanks, two lines: stable or not, how many roots grow, the fastest
// with its e-folding time and owner (docs/rom.md, "Verdict with dissipation").
std::string verdict_with_dissipation(const ChainModel& m, const Spectrum& sp);

}  // namespace rc::rom
