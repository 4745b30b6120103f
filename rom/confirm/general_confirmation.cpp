#include "general_confirmation.hpp"

#include "chain_model.hpp"
#include "driven_frequencies.hpp"
#include "general_chain.hpp"
#include "recorded_command.hpp"
#include "table_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <stdexcept>

namespace rc::rom {
namespace fs = std::filesystem;
namespace {
using cd = std::complex<double>;

bool is_response_table_3d(const rc::ModeTable& t) {
  return t.viscous() && t.response_fit() && t.volume_cavity.present();
}

// The viscous tables the chain without axial symmetry can remake: 3-D response tables and axisymmetric Krylov ones.
bool is_remakeable(const rc::ModeTable& t) { return is_response_table_3d(t) || is_krylov_table(t); }

struct TankTable {
  std::string key;  // the scene's key, body[k].cavity[j]
  fs::path file;
  int body = 0;     // 0-based
};

// Every tank's table file with its scene key, body by body.
std::vector<TankTable> tank_tables(const Scene& scene) {
  std::vector<TankTable> out;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const auto& b = scene.bodies[k];
    const std::string key = "body[" + std::to_string(k + 1) + "].cavity";
    const int body = static_cast<int>(k);
    if (b.cavity) out.push_back({key, b.cavity->table, body});
    for (std::size_t j = 0; j < b.more_cavities.size(); ++j)
      out.push_back({key + "[" + std::to_string(j + 2) + "]", b.more_cavities[j].table, body});
  }
  return out;
}

// The viscous tanks' table files (each once), with the bodies that carry them.
std::vector<std::pair<fs::path, std::set<int>>> viscous_tables(const Scene& scene) {
  std::vector<std::pair<fs::path, std::set<int>>> out;
  for (const TankTable& t : tank_tables(scene)) {
    if (!rc::read_mode_table(t.file).viscous()) continue;
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& x) { return x.first == t.file; });
    if (it == out.end()) it = out.insert(out.end(), {t.file, {}});
    it->second.insert(t.body);
  }
  return out;
}

// The arguments that remake a 3-D response table exact at `exact_at` (none: no --exact-at) into `output`, at another
// Ekman number when `ekman` > 0: its recorded command line with -o, any earlier --exact-at and, then, --ekman
// replaced; a `volume` file from the text the table stores when the recorded path is gone. `coarsen` > 1 makes
// every element size that many times the table's: its interior and wall sizes (the table records both) and a
// recorded --near-wall-size; the wall layers' total thickness is physics (the Ekman layers') and stays, the first
// layer then at most that thick.
std::vector<std::string> remake_arguments(const rc::ModeTable& t, const std::vector<cd>& exact_at,
                                          const fs::path& output, const fs::path& scratch, double ekman = 0,
                                          double coarsen = 1) {
  const std::vector<std::string> w = shell_words(t.command_line);
  if (w.size() < 2 || (w[1] != "ellipsoid" && w[1] != "volume"))
    throw std::runtime_error("its recorded command line is not 'cavity-modes ellipsoid|volume ...': " + t.command_line);
  std::vector<std::string> args{w[1]};
  bool have_file = w[1] != "volume";
  double wall_layer = 0, near_wall = 0;
  for (std::size_t i = 2; i < w.size(); ++i) {
    const std::string& word = w[i];
    if (word.size() < 2 || word[0] != '-') {
      if (!have_file && !fs::exists(word) && !t.geometry_text.empty()) {
        const fs::path file = scratch / ("volume" + fs::path(word).extension().string());
        std::ofstream(file, std::ios::binary) << t.geometry_text;
        args.push_back(file.string());
      } else {
        args.push_back(word);
      }
      have_file = true;
      continue;
    }
    const auto eq = word.find('=');
    const std::string name = word.substr(0, eq);
    const bool valued = eq == std::string::npos && i + 1 < w.size();
    const std::string value = eq != std::string::npos ? word.substr(eq + 1) : valued ? w[i + 1] : "";
    if (name == "--wall-layer") wall_layer = std::stod(value);
    if (coarsen != 1 && name == "--near-wall-size") near_wall = std::stod(value);
    const bool resized = coarsen != 1 && (name == "--mesh-size" || name == "--wall-size" || name == "--near-wall-size");
    if (name == "-o" || name == "--output" || name == "--exact-at" || (ekman > 0 && name == "--ekman") || resized) {
      if (eq == std::string::npos) ++i;  // its value is the next word
      continue;
    }
    args.push_back(word);
  }
  if (ekman > 0) args.insert(args.end(), {"--ekman", number_text(ekman)});
  if (coarsen != 1) {
    double wall = coarsen * t.mesh_h_wall;
    if (wall_layer > 0) wall = std::min(wall, wall_layer);
    args.insert(args.end(), {"--mesh-size", number_text(coarsen * t.mesh_h), "--wall-size", number_text(wall)});
    if (near_wall > 0) args.insert(args.end(), {"--near-wall-size", number_text(coarsen * near_wall)});
  }
  if (!exact_at.empty()) args.insert(args.end(), {"--exact-at", complex_list(exact_at)});
  args.insert(args.end(), {"-o", output.string()});
  return args;
}

// The table frequencies at which an axisymmetric tank on a body spinning at ω is driven at the turning-frame
// frequencies f: its m = 1 response at f and at −f̄ (a body without axial symmetry mixes the two), each s = f/ω as
// (26)'s table takes it (tank_frequencies: conjugated when ω < 0).
std::vector<cd> axisymmetric_frequencies(double omega, const std::vector<cd>& f) {
  std::vector<cd> sigma;
  for (const cd& x : f) sigma.insert(sigma.end(), {x - omega, -std::conj(x) - omega});
  return tank_frequencies(omega, sigma);
}

// The arguments that remake `t` into `output`: exact at `s` (none: as it was), at another Ekman number (`ekman` > 0),
// and on another mesh of its family — a 3-D table `coarsen` times as coarse, an axisymmetric one `finer` levels up.
std::vector<std::string> remake_any(const rc::ModeTable& t, const std::vector<cd>& s, const fs::path& output,
                                    const fs::path& scratch, double ekman = 0, double coarsen = 1, int finer = 0) {
  if (is_response_table_3d(t)) return remake_arguments(t, s, output, scratch, ekman, coarsen);
  return remake_response_arguments(t, {s, ekman, finer}, output, scratch);
}

// Remakes every viscous table exact at the tank frequencies of the frequencies f at which its bodies' tanks are driven
// (driven_frequencies.hpp): s = f/ω_k for a 3-D table (its rows hold λ > 0, the conjugates the rest), s = f/ω_k and
// −f̄/ω_k for an axisymmetric one; the file replaced only when cavity-modes succeeded.
void remake_tables(const Scene& scene, const GeneralChain& g, const std::vector<std::vector<cd>>& driven,
                   const std::string& binary, const fs::path& scratch, const ProgramRunner& run, std::ostream& log) {
  for (const auto& [file, bodies] : viscous_tables(scene)) {
    const rc::ModeTable t = rc::read_mode_table(file);
    std::vector<cd> s;
    for (const int k : bodies) {
      const std::vector<cd>& f = driven[static_cast<std::size_t>(k)];
      if (!is_response_table_3d(t)) {
        for (const cd& x : axisymmetric_frequencies(g.spins[k], f)) s.push_back(x);
        continue;
      }
      for (const cd& x : f) s.push_back(x / g.spins[k]);
    }
    const fs::path tmp = refining_name(file);
    std::vector<std::string> args{binary};
    for (auto& a : remake_any(t, s, tmp, scratch)) args.push_back(std::move(a));
    log << "  " << file.string() << ": R made exact at " << s.size() << " frequencies" << std::endl;
    run_and_replace(args, file, tmp, scratch, run);
  }
}

// The roots to confirm: one of each pair σ, −σ̄ (Re σ ≤ 0), not neutral (σ = 0, −ω0), within the response tables'
// window; all of them, or those a verdict rests on — the growing ones and the bodies' roots, taken as those that decay more slowly
// than half the tanks' slowest pole (a fluid root decays about as fast as its pole) —, or else the least damped one.
std::vector<cd> selected_roots(const GeneralChain& g, const GeneralSpectrum& sp, bool all) {
  const Verdict& v = sp.verdict;
  double slowest_pole = 1e300;
  for (const GeneralMode& m : g.modes)
    if (m.damped()) slowest_pole = std::min(slowest_pole, m.lambda.imag());
  std::vector<cd> candidates, chosen;
  // Neutral roots are left out as the verdict leaves them: σ = 0, and σ = ±ω0 where a free chain's rigid turn in
  // space sits in the turning frame (general_system.cpp); no table moves them.
  const double spin = std::abs(g.spin);
  for (const cd& r : sp.roots) {
    const bool neutral = std::abs(r) <= v.tolerance || (!g.periodic() && std::abs(r + spin) <= v.tolerance);
    if (neutral || r.real() > 0) continue;
    if (g.response_window > 0 && std::abs(r.real()) > g.response_window) continue;
    candidates.push_back(r);
    if (-r.imag() > v.noise || r.imag() < 0.5 * slowest_pole) chosen.push_back(r);
  }
  if (all || candidates.empty()) return candidates;
  if (!chosen.empty()) return chosen;
  return {*std::min_element(candidates.begin(), candidates.end(), [](cd a, cd b) { return a.imag() < b.imag(); })};
}

// |a − b|, the real parts compared modulo ν when ν > 0 (Floquet exponents).
double distance(cd a, cd b, double nu) {
  double re = a.real() - b.real();
  if (nu > 0) re -= nu * std::round(re / nu);
  return std::hypot(re, a.imag() - b.imag());
}

cd nearest(const std::vector<cd>& roots, cd r, double nu) {
  return *std::min_element(roots.begin(), roots.end(),
                           [&](cd a, cd b) { return distance(a, r, nu) < distance(b, r, nu); });
}

}  // namespace

bool has_viscous_tables(const Scene& scene) { return !viscous_tables(scene).empty(); }

void remake_at_ekman(const fs::path& table, double ekman, const fs::path& output, const std::string& binary,
                     const fs::path& scratch, const ProgramRunner& run) {
  std::vector<std::string> args{binary};
  for (auto& a : remake_any(rc::read_mode_table(table), {}, refining_name(output), scratch, ekman))
    args.push_back(std::move(a));
  run_and_replace(args, output, refining_name(output), scratch, run);
}

void remake_on_another_mesh(const fs::path& table, double coarsen, const fs::path& output, const std::string& binary,
                             const fs::path& scratch, const ProgramRunner& run) {
  const rc::ModeTable t = rc::read_mode_table(table);
  const bool axisymmetric = is_krylov_table(t);  // one level finer; a 3-D table `coarsen` times as coarse
  if (!axisymmetric && !(t.mesh_h > 0 && t.mesh_h_wall > 0))
    throw std::runtime_error(table.string() + ": the table records no interior and wall element sizes to coarsen");
  std::vector<std::string> args{binary};
  for (auto& a : remake_any(t, {}, refining_name(output), scratch, 0, axisymmetric ? 1 : coarsen, axisymmetric ? 1 : 0))
    args.push_back(std::move(a));
  run_and_replace(args, output, refining_name(output), scratch, run);
}

void check_general_refinable(const Scene& scene) {
  for (const auto& [key, file, body] : tank_tables(scene)) {
    const rc::ModeTable t = rc::read_mode_table(file);
    if (!t.viscous()) continue;
    if (!is_remakeable(t))
      throw SceneError(scene.file.string() + ": " + key + ".table " + file.string() + ": a chain without axial "
                       "symmetry is confirmed by remaking its viscous tanks' response tables (3-D: cavity-modes "
                       "ellipsoid|volume --ekman Ek --sigma 0:TO:N -o FILE.h5; axisymmetric, Krylov: cavity-modes "
                       "response SHAPE --ekman Ek --sigma FROM:TO:N -o FILE.h5), and this is not one");
    if (t.command_line.empty())
      throw SceneError(scene.file.string() + ": " + key + ".table " + file.string() + ": it records no command line");
    if (t.command_line.find("--boundary-layer") != std::string::npos)
      throw SceneError(scene.file.string() + ": " + key + ".table " + file.string() + ": a boundary-layer table is "
                       "exact where it was made exact (value and slope): remake it with --exact-at at the root that "
                       "matters until the root stays (one or two rounds), and measure its mesh error on a finer "
                       "--mesh-size (docs/volume.md section 9; bench/boundary_layer_spacecraft.py)");
  }
}

GeneralConfirmation confirm_general(const Scene& scene, bool all, double tolerance, const std::string& binary,
                                    const fs::path& scratch, const ProgramRunner& run, std::ostream& log,
                                    int max_rounds, std::optional<double> frame) {
  check_general_refinable(scene);
  GeneralConfirmation out;
  GeneralChain g = build_general_chain(scene, nullptr, frame);
  out.tables = static_cast<int>(viscous_tables(scene).size());
  out.spectrum = general_spectrum(g);
  out.table_roots = selected_roots(g, out.spectrum, all);
  std::vector<cd> current = out.table_roots;
  out.moved.assign(current.size(), 0.0);
  out.converged = current.empty() || out.tables == 0;
  const double spin = g.spin;
  // At two spins a root is a Floquet exponent (Re σ modulo ν = 2π/T), compared so.
  const double nu = g.periodic() ? 2 * std::numbers::pi / g.period : 0.0;
  while (!out.converged && out.rounds < max_rounds) {
    ++out.rounds;
    log << "round " << out.rounds << ": the tables remade with R exact at " << current.size() << " root(s)" << std::endl;
    remake_tables(scene, g, driven_frequencies(g, current, log), binary, scratch, run, log);
    g = build_general_chain(scene, nullptr, frame);
    out.spectrum = general_spectrum(g);
    double worst = 0;
    for (std::size_t i = 0; i < current.size(); ++i) {
      const cd next = nearest(out.spectrum.roots, current[i], nu);
      out.moved[i] = distance(next, current[i], nu) / std::max(std::abs(current[i]), std::abs(spin));
      worst = std::max(worst, out.moved[i]);
      current[i] = next;
    }
    log << "  the roots moved by " << worst << " at most (relative)" << std::endl;
    out.converged = worst <= tolerance;
  }
  out.confirmed = current;
  return out;
}

}  // namespace rc::rom
