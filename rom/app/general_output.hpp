// What `chain-rom spectrum` prints for a chain without axial symmetry (rom/general/; docs/rom.md, "Bodies and tanks
// without axial symmetry"): its roots in the frame turning with the bodies, the verdict, and the tanks' coverage.
#pragma once

#include "general_chain.hpp"
#include "general_system.hpp"

#include <ostream>
#include <string>

namespace rc::rom {

void print_general_spectrum(std::ostream& os, const GeneralChain& g, const GeneralSpectrum& sp);

// {"model": "general", "frame": "turning", "spin", "roots": [[re, im], ...], "stable", "margin", "growth", "growing",
//  "tolerance", "fluid_modes", "coverage": [[body, share] per tank]}
std::string general_spectrum_json(const GeneralChain& g, const GeneralSpectrum& sp);

}  // namespace rc::rom
