// Response tables made exact at the chain's roots (chain-rom confirm --refine-tables; docs/rom.md, "Confirmed
// roots"). A Krylov response table's R is the Hermitian projection of the fluid's response on a rational Krylov
// space; when the forced solution x(s) at a frequency s lies in that space the projection returns it, so R_table(s)
// is R(s) to rounding there (viscous/krylov_response.hpp in modes/). Remaking a tank's table with the tank
// frequencies of the chain's confirmed roots as such points (cavity-modes response ... --exact-at) makes the table's
// (22) vanish where the true (22) does: `spectrum`, `run` and `sweep` then report the confirmed roots themselves,
// not the roots of a table accurate only to its --max-fit-error.
#pragma once

#include "chain_model.hpp"
#include "scene.hpp"

#include <complex>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace rc::rom {

// The tank's own frequencies s at the chain's roots sigma, as its table takes them (chain_model.cpp's mirror at a
// negative spin: s = (sigma + omega)/omega, conjugated when omega < 0), without repeats.
std::vector<std::complex<double>> tank_frequencies(double omega, const std::vector<std::complex<double>>& roots);

// True for a Krylov response table (cavity-modes response SHAPE ... -o FILE.h5 without --fit or --galerkin), the one
// kind of axisymmetric table that can be made exact at given frequencies.
bool is_krylov_table(const rc::ModeTable& table);

// How a Krylov response table is remade from its recorded command line: exact at `exact_at` (none: as it was), at
// another Ekman number (`ekman` > 0), on its mesh family's level `finer` levels up (every element size halved per
// level: cavity-modes response --mesh-level).
struct ResponseRemake {
  std::vector<std::complex<double>> exact_at;
  double ekman = 0;
  int finer = 0;
};

// The arguments after the program's name that remake the Krylov response table `table` as `remake` says, written to
// `output` (a section's file from the text the table stores, into `scratch`). Throws std::runtime_error with one line
// when the table is not a Krylov response table or its command line cannot be read back.
std::vector<std::string> remake_response_arguments(const rc::ModeTable& table, const ResponseRemake& remake,
                                                   const std::filesystem::path& output,
                                                   const std::filesystem::path& scratch);

// The arguments after the program's name that remake `table` — a Krylov response table — with R exact at
// `exact_at`, written to `output`: its recorded command line with -o and any earlier --exact-at replaced (a
// section's file from the text the table stores, into `scratch`). Throws std::runtime_error with one line when the
// table is not a Krylov response table or its command line cannot be read back.
std::vector<std::string> refine_arguments(const rc::ModeTable& table, const std::vector<std::complex<double>>& exact_at,
                                          const std::filesystem::path& output, const std::filesystem::path& scratch);

// Runs a program (full argument vector, args[0] the binary) with its output into a log file; returns its exit
// status, or -1 when it cannot start.
using ProgramRunner = std::function<int(const std::vector<std::string>& args, const std::string& log_file)>;

// Runs `args` (the binary first, its output FILE.refining.h5 beside `file`) and, when it succeeds, replaces `file`
// with that output; otherwise removes it and throws std::runtime_error naming the table (which is unchanged).
void run_and_replace(const std::vector<std::string>& args, const std::filesystem::path& file,
                     const std::filesystem::path& output, const std::filesystem::path& scratch, const ProgramRunner& run);

// Where a table's remade version is written before it replaces the table: FILE.refining.h5 beside it.
std::filesystem::path refining_name(const std::filesystem::path& file);

struct RefinedTable {
  std::filesystem::path file;
  int exact_points = 0;
  double seconds = 0;
};

// Throws SceneError naming the table when some viscous tank of `m` has a table that cannot be refined (not a Krylov
// response table, or no command line): checked before any work.
void check_refinable(const Scene& scene, const ChainModel& m);

// Remakes every viscous tank's table (one run per table file, with the frequencies of every body that uses it) and
// replaces the file only when cavity-modes succeeded (it writes to FILE.refining.h5 first). Writes one line per
// table to `log`. Throws std::runtime_error naming the table when a run fails (the old table is then untouched).
std::vector<RefinedTable> refine_tables(const Scene& scene, const ChainModel& m,
                                        const std::vector<std::complex<double>>& roots, const std::string& binary,
                                        const std::filesystem::path& scratch, const ProgramRunner& run,
                                        std::ostream& log);

}  // namespace rc::rom
