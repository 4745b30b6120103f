// Roots of a chain without axial symmetry confirmed with the fluid's own response (chain-rom confirm SCENE
// --refine-tables; docs/rom.md, "Confirmed roots"). Its viscous tanks are response tables — 3-D ones (docs/volume.md §7,
// "The response table") or axisymmetric Krylov ones (docs/viscous.md, "Krylov response table") —, whose R is the
// fluid's own to rounding at the frequencies they were made exact at: each round remakes every such table (cavity-modes
// ellipsoid|volume ... or cavity-modes response SHAPE ... with --exact-at, from its recorded command line) exact at the
// tank frequencies s = σ/ω0 of the selected roots σ (the frame turning at ω0; an axisymmetric tank's m = 1 response at
// −σ̄/ω0 too), and solves the chain again. A root
// the remade tables leave where they were made exact satisfies the characteristic equation with the fluid's own R:
// the rounds stop when every selected root moves by less than the tolerance (relative to max(|σ|, |ω0|)). At two
// spins a root is a Floquet exponent and each tank is driven at the frequencies of its harmonics: the tables are made
// exact at those that carry the motion (driven_frequencies.hpp), and the roots compared modulo the period's frequency.
#pragma once

#include "general_system.hpp"
#include "scene.hpp"
#include "table_refinement.hpp"

#include <complex>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

struct GeneralConfirmation {
  std::vector<std::complex<double>> table_roots;  // the selected roots with the tables as they were
  std::vector<std::complex<double>> confirmed;    // the same roots after the last round
  std::vector<double> moved;                      // each root's last step, relative
  int rounds = 0, tables = 0;
  bool converged = false;
  GeneralSpectrum spectrum;                       // the last round's, every root
};

// Throws SceneError naming the key when a viscous tank's table is neither a 3-D response table nor an axisymmetric
// Krylov one, or records no command line (checked before any work).
void check_general_refinable(const Scene& scene);

// Makes the viscous table `table` again from its recorded command line on another mesh of its family (any --exact-at
// dropped) into `output`, through output.refining.h5: a 3-D response table on a mesh `coarsen` times as coarse (its
// interior, wall and near-wall element sizes), an axisymmetric Krylov table one mesh level finer (--mesh-level, every
// size halved). Throws std::runtime_error naming it when cavity-modes fails or a 3-D table records no element sizes.
void remake_on_another_mesh(const std::filesystem::path& table, double coarsen, const std::filesystem::path& output,
                    const std::string& binary, const std::filesystem::path& scratch, const ProgramRunner& run);

// True when some tank of the scene has a viscous table.
bool has_viscous_tables(const Scene& scene);

// Makes the response table `table` (3-D, or axisymmetric Krylov) again from its recorded command line at the Ekman
// number `ekman` (any
// --exact-at dropped) into `output`, through output.refining.h5. Throws std::runtime_error naming it when cavity-modes
// fails.
void remake_at_ekman(const std::filesystem::path& table, double ekman, const std::filesystem::path& output,
                     const std::string& binary, const std::filesystem::path& scratch, const ProgramRunner& run);

// The roots a verdict rests on — the growing ones and those that decay more slowly than half the tanks' slowest pole
// (the bodies') — or, when `all`, every root with Re σ ≤ 0 within the response tables' window (one of each pair σ,
// −σ̄), confirmed in at most `max_rounds` rounds (`frame`: build_general_chain's, for tests). One line per table and round to
// `log`. Throws std::runtime_error when a table cannot be remade (the old table is then untouched).
GeneralConfirmation confirm_general(const Scene& scene, bool all, double tolerance, const std::string& binary,
                                    const std::filesystem::path& scratch, const ProgramRunner& run, std::ostream& log,
                                    int max_rounds = 4, std::optional<double> frame = std::nullopt);

}  // namespace rc::rom
