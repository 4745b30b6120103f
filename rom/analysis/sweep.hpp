// Stability maps (`chain-rom sweep`): the verdict and margin of a scene over one or two of its
// numeric values. The scene is parsed once and its mode tables read once; each point changes the
// value in the parsed Scene and rebuilds only the model (docs/rom.md, "Stability maps").
#pragma once

#include "chain_model.hpp"
#include "scene.hpp"
#include "spectrum.hpp"

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc::rom {

struct SweepError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A numeric scene value named by a key such as `body[2].spin`, `joint[1].stiffness`,
// `body[3].cavity.density`, `system.gravity`, `support.friction` (1-based indices), or a cavity's
// table out of a family of tables, `body[2].cavity.table=cone_h%.2f.h5`: the swept number is put into
// the file name by the pattern's one printf conversion (docs/rom.md, "Stability maps"); or
// `system.spin_factor`, a common factor on every body's spin (the scene's spins times the value).
struct ParamKey {
  std::string text;   // as the user wrote it
  enum class Where { system, support, body, cavity, joint } where = Where::system;
  int index = 0;      // 0-based body or joint index
  std::string field;  // e.g. "spin", "density", "table"
  std::string table_pattern;  // field "table" only: file name with one %e/%f/%g conversion
  std::vector<double> base_spins;  // system.spin_factor only: the scene's spins, which the factor multiplies
  bool is_table() const { return field == "table"; }
  bool is_spin_factor() const { return where == Where::system && field == "spin_factor"; }
};

// Parses KEY and checks it against the scene (index in range, the body has a cavity, ...).
// Throws SweepError("<option> <KEY>: <cause>") — one line naming the key.
ParamKey parse_param_key(const std::string& key, const Scene& scene, const std::string& option = "--param");
// The value the key names, in the scene (read and write); numeric keys only (not is_table()).
double& param_ref(Scene& scene, const ParamKey& key);
// Writes `value` into the scene: the number itself, or for a table key the table file it names.
void set_param(Scene& scene, const ParamKey& key, double value);
// A table key's file for `value` (the pattern formatted with it; relative to the current folder).
std::filesystem::path table_of(const ParamKey& key, double value);
// Throws SweepError if `value` is outside the key's allowed range (docs/scene-format.md).
void check_param_value(const ParamKey& key, double value, const std::string& option);

struct SweepAxis {
  ParamKey key;
  double from = 0, to = 0;
  int steps = 1;  // >= 1 points from `from` to `to` inclusive (1: `from` only)
  double value(int i) const { return steps == 1 ? from : from + (to - from) * i / (steps - 1); }
};

struct SweepPoint {
  double v1 = 0, v2 = 0;
  bool ok = false;    // false: the model could not be built or solved there (see error)
  bool tracked = false;  // roots tracked from the neighbouring point (root_tracking.hpp), not by the eigen-solver
  Verdict verdict;
  // A stable undamped chain's distance to the threshold (rad/s, krein_gap.hpp); NaN otherwise.
  double gap = std::numeric_limits<double>::quiet_NaN();
  std::string error;
};

struct SweepResult {
  std::vector<SweepPoint> points;  // axis-1 index outer, axis-2 index inner
  int failed = 0;
  long tracked = 0;          // points whose roots were tracked; the others went to the eigen-solver
  std::string first_fallback;  // why the first tracked point that fell back to the eigen-solver did so
  double wall_seconds = 0;
  int threads = 1;
};

// Progress callback: (points done, total, seconds elapsed).
using SweepProgress = std::function<void(long, long, double)>;

// Runs the sweep on `threads` threads (0: std::thread::hardware_concurrency()). The scene's own
// tables and those of a table key's family are read into `tables` before the threads start; a
// family table that cannot be read throws SweepError naming the key and the file, before any point.
// With `track` (not for a family of tables) the points are walked in lines and each point's roots are tracked
// from its neighbours' (root_tracking.hpp): a 2-D map walks its first column, then its rows in parallel; a 1-D
// sweep is cut into one stretch per thread. A line starts with the eigen-solver, and any point whose tracked
// roots are not accepted goes to it too. Without `track` every point goes to the eigen-solver.
SweepResult run_sweep(const Scene& base, TableCache& tables, const SweepAxis& a1,
                      const std::optional<SweepAxis>& a2, int threads = 0,
                      const SweepProgress& progress = {}, bool track = true);

// CSV: header `<KEY1>[,<KEY2>],stable,margin,nonreal,gap`, one row per point; points where the model
// could not be built have stable, margin, nonreal and gap = nan; gap is nan where it is not defined. Temporary name, then rename.
void write_sweep_csv(const SweepResult& r, const SweepAxis& a1, const std::optional<SweepAxis>& a2,
                     const std::filesystem::path& out);

}  // namespace rc::rom
