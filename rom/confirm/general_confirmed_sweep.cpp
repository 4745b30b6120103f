#include "general_confirmed_sweep.hpp"

#include "general_confirmation.hpp"
#include "mode_table.hpp"
#include "tank_responses.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {

// Every tank of the scene, with its body's spin.
struct TankRef {
  CavitySpec* cavity;
  double spin;
};
std::vector<TankRef> tanks_of(Scene& s) {
  std::vector<TankRef> out;
  for (BodySpec& b : s.bodies) {
    if (b.cavity) out.push_back({&*b.cavity, b.spin});
    for (CavitySpec& c : b.more_cavities) out.push_back({&c, b.spin});
  }
  return out;
}

// Points the point's viscous tanks at tables of their own in `folder`: made again at the point's Ekman number
// ν/(|ω| L²) when `remake` (one per table file and Ek), else copied. Returns the Ekman numbers, tank by tank, and
// counts the cavity-modes runs.
std::vector<double> own_tables(Scene& s, bool remake, const fs::path& folder, const std::string& binary,
                               const fs::path& scratch, const ProgramRunner& run, int& runs) {
  std::vector<double> ekman;
  std::map<std::string, fs::path> made;
  for (TankRef& t : tanks_of(s)) {
    const rc::ModeTable table = rc::read_mode_table(t.cavity->table);
    if (!table.viscous()) continue;
    if (t.spin == 0) throw std::runtime_error("a body with a viscous tank does not spin here: no Ekman number");
    const double ek = *t.cavity->viscosity / (std::abs(t.spin) * t.cavity->scale * t.cavity->scale);
    ekman.push_back(ek);
    std::ostringstream key;
    key << t.cavity->table.string() << '|' << std::setprecision(12) << (remake ? ek : table.ekman);
    auto it = made.find(key.str());
    if (it == made.end()) {
      const fs::path file = folder / ("tank" + std::to_string(made.size() + 1) + ".h5");
      if (remake) {
        remake_at_ekman(t.cavity->table, ek, file, binary, scratch, run);
        ++runs;
      } else {
        fs::copy_file(t.cavity->table, file, fs::copy_options::overwrite_existing);
      }
      it = made.emplace(key.str(), file).first;
    }
    t.cavity->table = it->second;
  }
  return ekman;
}

ConfirmedSweepPoint evaluate(Scene s, double value, bool remake, const fs::path& folder, const std::string& binary,
                             double tolerance, const fs::path& scratch, const ProgramRunner& run) {
  const auto t0 = std::chrono::steady_clock::now();
  ConfirmedSweepPoint p;
  p.value = value;
  int runs = 0;
  p.ekman = own_tables(s, remake, folder, binary, scratch, run, runs);
  std::ostringstream quiet;
  const GeneralConfirmation c = confirm_general(s, false, tolerance, binary, scratch, run, quiet);
  for (std::size_t i = 0; i < c.confirmed.size(); ++i) {
    const bool settled = c.moved[i] <= tolerance;
    p.roots.push_back({"root " + std::to_string(i + 1), c.confirmed[i], settled});
    p.unconfirmed += settled ? 0 : 1;
  }
  p.stable = c.spectrum.verdict.stable;
  p.growth = c.spectrum.verdict.growth;
  p.growing = c.spectrum.verdict.growing;
  p.solves = runs + c.rounds * c.tables;
  p.ok = true;
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace

std::vector<ConfirmedSweepPoint> run_general_confirmed_sweep(const Scene& base, const SweepAxis& axis,
                                                             const std::string& binary, double tolerance,
                                                             const ProgramRunner& run, std::ostream& log) {
  check_general_refinable(base);
  const bool remake = moves_viscous_ekman(base, axis.key);
  log << "chain-rom sweep: a chain without axial symmetry, each point's roots confirmed with its response tables "
      << (remake ? "made again at the point's Ekman number and " : "") << "remade exact at its roots (docs/rom.md, "
      << "\"Spin sweeps of chains without axial symmetry\"); the scene's table files are left as they are" << std::endl;
  const ScratchFolder scratch;
  std::vector<ConfirmedSweepPoint> points;
  for (int i = 0; i < axis.steps; ++i) {
    const double v = axis.value(i);
    Scene s = base;
    set_param(s, axis.key, v);
    const fs::path folder = scratch.path / ("point" + std::to_string(i + 1));
    fs::create_directories(folder);
    ConfirmedSweepPoint p;
    try {
      p = evaluate(s, v, remake, folder, binary, tolerance, scratch.path, run);
    } catch (const SceneError&) {
      throw;  // the scene, not the point: the same everywhere
    } catch (const std::exception& e) {
      p.value = v;
      p.error = e.what();
    }
    std::error_code gone;
    fs::remove_all(folder, gone);
    log_sweep_point(log, axis, p, i, std::to_string(p.solves) + " cavity-modes runs");
    points.push_back(p);
  }
  return points;
}

}  // namespace rc::rom
