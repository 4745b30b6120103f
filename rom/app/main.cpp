// chain-rom: characteristic roots and time histories of a chain of spinning bodies with
// fluid-filled cavities (docs/physics.md §3-4). One-line error and exit code 1 on bad input.
#include "bench.hpp"
#include "chain_model.hpp"
#include "empty_argument.hpp"
#include "companion_check.hpp"
#include "confirm_command.hpp"
#include "confirmed_sweep.hpp"
#include "served_response.hpp"
#include "linear_validity.hpp"
#include "nonlinear_run.hpp"
#include "output.hpp"
#include "propagation.hpp"
#include "scene.hpp"
#include "spectrum.hpp"
#include "sweep.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace {

// Runs argv[0] with the arguments (no shell); returns its exit status, or -1 if it cannot start.
int run_program(const std::vector<std::string>& args, bool quiet = false) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (quiet) {
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid;
  const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// `run` with [run] model = "nonlinear" (docs/rom.md, "Nonlinear chain").
int run_nonlinear(const rc::rom::Scene& scene, const std::string& out_file) {
  const rc::rom::NonlinearChain chain = rc::rom::nonlinear_chain(scene);
  const rc::rom::NonlinearHistory h =
      rc::rom::integrate_nonlinear(chain, rc::rom::nonlinear_initial_state(scene, chain), scene.run);
  rc::rom::write_nonlinear_history(h, chain.size(), out_file);
  std::cout << "wrote " << out_file << ": " << h.base.t.size() << " samples, model nonlinear (Lie-group Dormand-Prince 5(4), tolerance "
            << scene.run.tolerance << ", " << h.base.integrator_steps << " steps, " << h.rejected_steps
            << " rejected), " << h.base.wall_seconds << " s\n";
  if (h.viscous_spin_change > rc::rom::kEkmanTolerance)
    std::fprintf(stderr, "chain-rom: warning: a body with a viscous tank changed its spin by %.3g %%: its table holds "
                         "for the scene's spin (Ek to %.3g %%), and the modes were scaled as if Ek stayed (docs/rom.md, "
                         "\"Nonlinear chain\", \"Viscous tanks\")\n",
                 100 * h.viscous_spin_change, 100 * rc::rom::kEkmanTolerance);
  const bool damped = std::any_of(chain.joints.begin(), chain.joints.end(),
                                  [](const rc::rom::ChainJoint& j) { return j.friction > 0 || j.axial_friction > 0; });
  if (!h.integrals_valid) {
    std::cout << "energy: not an integral with fluid tanks in the nonlinear model (docs/rom.md, \"Nonlinear chain\")\n";
    return 0;
  }
  std::cout << "energy: H(0) = " << h.base.H.front() << ", H(end) = " << h.base.H.back() << ", "
            << (damped ? "largest relative increase per sample " : "largest relative drift ") << h.base.max_energy_drift
            << "; angular momentum " << (chain.free_chain ? "(vector)" : "(about the vertical through O_1)")
            << ": largest relative drift " << h.max_momentum_drift << "\n";
  return 0;
}

// The Python that draws sweep maps: Debian's (python3-matplotlib), or $CHAIN_ROM_PYTHON.
std::string plot_python() {
  const char* env = std::getenv("CHAIN_ROM_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"chain-rom: stability and motion of a chain of n spinning bodies with fluid-filled "
               "cavities (reads mode tables written by cavity-modes; scene format: docs/scene-format.md)"};
  app.require_subcommand(1);
  std::string scene_file, out_file;
  bool json = false;
  auto* spec = app.add_subcommand("spectrum", "characteristic roots sigma (e^{i sigma t}), stability verdict, margin");
  spec->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  spec->add_flag("--json", json, "print {\"roots\", \"stable\", \"margin\", \"det_residual\"} as JSON");
  rc::rom::ConfirmRequest confirm_req;
  bool spec_confirm = false;
  spec->add_flag("--confirm", spec_confirm, "viscous tanks: what chain-rom confirm prints, the roots the verdict rests "
                                            "on with the fluid's own response (docs/rom.md, \"Confirmed roots\")");
  spec->add_option("--cavity-modes", confirm_req.cavity_modes, "with --confirm: the cavity-modes binary (default: "
                                                               "$CAVITY_MODES, else the one beside chain-rom's build folder)");
  auto* confirm = app.add_subcommand(
      "confirm", "the roots of spectrum checked against the viscous tanks' own response: each body root and each "
                 "growing root iterated on (22) with R(s) by forced solves on the table's mesh (cavity-modes response "
                 "--serve), and the verdict from them (docs/rom.md, \"Confirmed roots\")");
  confirm->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  confirm->add_flag("--all", confirm_req.all, "every root, not only the body roots and the growing ones");
  confirm->add_option("--tolerance", confirm_req.tolerance, "relative step at which a root counts as converged "
                                                            "(default 1e-10)")->check(CLI::PositiveNumber);
  confirm->add_option("--cavity-modes", confirm_req.cavity_modes, "the cavity-modes binary (default: $CAVITY_MODES, "
                                                                  "else the one beside chain-rom's build folder)");
  confirm->add_flag("--json", confirm_req.json, "print {\"roots\", \"stable\", \"growth\", \"unconfirmed\", ...} as JSON");
  auto* run = app.add_subcommand("run", "time histories of u_k and the fluid coordinates with the energy monitored");
  run->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  run->add_option("-o,--output", out_file, "output file: HDF5, or CSV when the name ends in .csv")->required();

  auto* sweep = app.add_subcommand(
      "sweep", "stability map: verdict, margin and number of non-real roots over one or two scene values "
               "(keys like body[1].spin, joint[2].stiffness, body[3].cavity.density, system.gravity; docs/rom.md)");
  std::string key1, key2, png_file;
  double from1 = 0, to1 = 0, from2 = 0, to2 = 0;
  int steps1 = 0, steps2 = 0, threads = 0;
  sweep->add_option("SCENE", scene_file, "scene file (TOML)")->required();
  sweep->add_option("--param", key1, "scene value to sweep, e.g. body[1].spin (1-based indices), or a family of "
                                     "tables, body[2].cavity.table=cone_h%.2f.h5")->required();
  sweep->add_option("--from", from1, "first value")->required();
  sweep->add_option("--to", to1, "last value")->required();
  sweep->add_option("--steps", steps1, "number of values, from..to inclusive (>= 1)")->required();
  sweep->add_option("--param2", key2, "second scene value (2D map)");
  auto* f2 = sweep->add_option("--from2", from2, "first value of --param2");
  auto* t2 = sweep->add_option("--to2", to2, "last value of --param2");
  auto* s2 = sweep->add_option("--steps2", steps2, "number of values of --param2 (>= 1)");
  sweep->add_option("-o,--output", out_file, "CSV: <key>[,<key2>],stable,margin,nonreal, one row per point")->required();
  sweep->add_option("--png", png_file, "also draw the map (scripts/plot_sweep.py with /usr/bin/python3 + matplotlib)");
  sweep->add_option("--threads", threads, "worker threads (default: all cores)");
  std::string sweep_cavity_modes;
  sweep->add_option("--cavity-modes", sweep_cavity_modes, "a key that moves a viscous tank's Ekman number (spin, "
                    "spin_factor, cavity scale): the cavity-modes binary that serves its forced solves (default: "
                    "$CAVITY_MODES, else the one beside chain-rom's build folder)");
  bool sweep_confirm = false;
  sweep->add_flag("--confirm", sweep_confirm, "viscous tanks: every point's body and growing roots confirmed with the "
                  "fluid's own response by forced solves (docs/rom.md, \"Confirmed roots\"; always so for a key that "
                  "moves a viscous tank's Ekman number)");
  bool no_track = false;
  sweep->add_flag("--no-track", no_track, "every point's roots by the eigen-solver (default: tracked from the "
                                          "neighbouring point's, checked, the eigen-solver where the check fails)");

  auto* bench = app.add_subcommand(
      "bench", "error against run time: the state at run.t_end by exact, gauss (step sweep) and rk45 (tolerance "
               "sweep) against an extended-precision reference, and the roots' error against the number of kept "
               "modes with and without static_correction (docs/rom.md, \"Benchmark\")");
  bench->add_option("SCENE", scene_file, "scene file (TOML) with a [run] section (t_end, initial state)")->required();
  bench->add_option("-o,--output", out_file, "CSV: part,method,parameter,value,steps,body,static_correction,"
                                             "spin_factor,coverage,wall_seconds,cpu_seconds,error");
  bench->add_option("--png", png_file, "also draw it (scripts/plot_bench.py with /usr/bin/python3 + matplotlib); needs -o");

  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    std::string msg = e.what();
    for (auto& ch : msg) if (ch == '\n') ch = ' ';
    return "chain-rom: error: " + msg + " (--help for usage)\n";
  });
  if (const std::string empty = rc::empty_argument_error(argc, argv); !empty.empty()) {
    std::fprintf(stderr, "chain-rom: error: %s\n", empty.c_str());  // a command-line error: exit 2
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help: 0; every command-line error: 2, whatever CLI11's own code (docs/rom.md).
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (sweep->parsed()) {
      using namespace rc::rom;
      const bool two = !key2.empty();
      if (two != (f2->count() > 0) || two != (t2->count() > 0) || two != (s2->count() > 0))
        throw SweepError("--param2, --from2, --to2 and --steps2 go together");
      if (steps1 < 1) throw SweepError("--steps " + std::to_string(steps1) + ": must be >= 1");
      if (two && steps2 < 1) throw SweepError("--steps2 " + std::to_string(steps2) + ": must be >= 1");
      if (two && key2 == key1) throw SweepError("--param2 " + key2 + ": same key as --param");
      const Scene scene = parse_scene(scene_file);
      SweepAxis a1{parse_param_key(key1, scene, "--param"), from1, to1, steps1};
      check_param_value(a1.key, from1, "--from (--param)");
      check_param_value(a1.key, to1, "--to (--param)");
      std::optional<SweepAxis> a2;
      if (two) {
        a2 = SweepAxis{parse_param_key(key2, scene, "--param2"), from2, to2, steps2};
        check_param_value(a2->key, from2, "--from2 (--param2)");
        check_param_value(a2->key, to2, "--to2 (--param2)");
      }
      const std::filesystem::path out(out_file);
      if (out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
        throw std::runtime_error(out_file + ": the output folder does not exist");
      const bool moves = moves_viscous_ekman(scene, a1.key) || (a2 && moves_viscous_ekman(scene, a2->key));
      const bool confirmed = moves || sweep_confirm;
      if (moves && a2)
        throw SweepError("a key that moves a viscous tank's Ekman number sweeps one value at a time (no --param2): "
                         "each point serves forced solves at its own Ek");
      if (sweep_confirm && a2) throw SweepError("--confirm sweeps one value at a time (no --param2)");
      if (sweep_confirm && !build_model(scene).viscous)
        throw SweepError("--confirm: the scene has no viscous tank (its roots are (22)'s own)");
      const std::string script = RC_PLOT_SWEEP_SCRIPT, python = plot_python();
      if (!png_file.empty()) {  // fail before the sweep, not after it
        if (!std::filesystem::exists(script))
          throw std::runtime_error("--png: " + script + " not found (the source tree's scripts/)");
        if (run_program({python, "-c", "import matplotlib, numpy"}, true) != 0)
          throw std::runtime_error("--png: " + python + " with matplotlib and numpy is needed to draw the map "
                                   "(apt-get install python3-matplotlib); nothing written");
      }
      if (confirmed) {
        const auto points = run_confirmed_sweep(scene, a1, cavity_modes_binary(sweep_cavity_modes), 1e-10, std::cerr);
        write_confirmed_sweep(points, a1, out);
        int stable = 0, failed = 0;
        for (const auto& p : points) {
          stable += p.ok && p.stable ? 1 : 0;
          failed += p.ok ? 0 : 1;
        }
        std::printf("wrote %s and its roots beside it: %zu points (%d stable, %d unstable, %d failed), roots of (22) "
                    "with the fluid's own response\n", out_file.c_str(), points.size(), stable,
                    static_cast<int>(points.size()) - stable - failed, failed);
        if (!png_file.empty()) {
          const int rc = run_program({python, script, out_file, "-o", png_file, "--growth"});
          if (rc != 0)
            throw std::runtime_error("--png: " + script + " failed (exit " + std::to_string(rc) + "); the CSV " +
                                     out_file + " was written, no PNG");
          std::printf("wrote %s\n", png_file.c_str());
        }
        return 0;
      }
      TableCache tables;
      // Validates the scene as given and reads its tables once; a dissipative chain's margin is a growth rate.
      const bool growth_map = build_model(scene, &tables).dissipative();
      const SweepResult r = run_sweep(scene, tables, a1, a2, threads, [](long d, long total, double el) {
        std::fprintf(stderr, "chain-rom sweep: %ld/%ld points, %.1f s, about %.0f s left\n", d, total, el,
                     el * static_cast<double>(total - d) / static_cast<double>(d));
      }, !no_track);
      write_sweep_csv(r, a1, a2, out);
      int stable = 0;
      for (const auto& p : r.points) stable += (p.ok && p.verdict.stable) ? 1 : 0;
      std::printf("wrote %s: %zu points (%d stable, %d unstable, %d failed), %.3g s on %d thread%s\n",
                  out_file.c_str(), r.points.size(), stable, static_cast<int>(r.points.size()) - stable - r.failed,
                  r.failed, r.wall_seconds, r.threads, r.threads == 1 ? "" : "s");
      std::printf("roots: %ld points tracked from their neighbours, %ld by the eigen-solver%s%s\n", r.tracked,
                  static_cast<long>(r.points.size()) - r.tracked - r.failed,
                  r.first_fallback.empty() ? "" : "; first fallback: ", r.first_fallback.c_str());
      std::fflush(stdout);
      if (r.failed > 0)
        for (const auto& p : r.points)
          if (!p.ok) {
            std::string msg = p.error;
            for (auto& ch : msg) if (ch == '\n') ch = ' ';
            std::fprintf(stderr, "chain-rom sweep: warning: %d points not evaluated (nan in the CSV); first at %s = %g: %s\n",
                         r.failed, key1.c_str(), p.v1, msg.c_str());
            break;
          }
      if (!png_file.empty()) {
        std::vector<std::string> cmd = {python, script, out_file, "-o", png_file};
        if (growth_map) cmd.push_back("--growth");
        const int rc = run_program(cmd);
        if (rc != 0)
          throw std::runtime_error("--png: " + script + " failed (exit " + std::to_string(rc) + "); the CSV " +
                                   out_file + " was written, no PNG");
        std::printf("wrote %s\n", png_file.c_str());
      }
      return 0;
    }
    if (bench->parsed()) {
      const std::string script = RC_PLOT_BENCH_SCRIPT, python = plot_python();
      if (!png_file.empty() && out_file.empty()) throw std::runtime_error("--png: needs -o (the CSV it is drawn from)");
      const std::filesystem::path out(out_file);
      if (!out_file.empty() && out.has_parent_path() && !std::filesystem::is_directory(out.parent_path()))
        throw std::runtime_error(out_file + ": the output folder does not exist");
      if (!png_file.empty()) {  // fail before the benchmark, not after it
        if (!std::filesystem::exists(script))
          throw std::runtime_error("--png: " + script + " not found (the source tree's scripts/)");
        if (run_program({python, "-c", "import matplotlib, numpy"}, true) != 0)
          throw std::runtime_error("--png: " + python + " with matplotlib and numpy is needed to draw the figure "
                                   "(apt-get install python3-matplotlib); nothing written");
      }
      const rc::rom::Scene scene = rc::rom::parse_scene(scene_file);
      const rc::rom::BenchResult r = rc::rom::run_bench(scene, {}, [](const rc::rom::BenchRow& row) {
        std::printf("%s\n", rc::rom::format_bench_row(row).c_str());
        std::fflush(stdout);
      });
      std::printf("t_end = %g s, first-order dimension %d, fastest root |sigma| = %.4g rad/s, reference: long "
                  "double (%d-bit mantissa)\n", r.t_end, r.dimension, r.spectral_radius, r.reference_mantissa_bits);
      if (!out_file.empty()) {
        rc::rom::write_bench_csv(r, out);
        std::printf("wrote %s: %zu rows\n", out_file.c_str(), r.rows.size());
      }
      if (!png_file.empty()) {
        const int rc = run_program({python, script, out_file, "-o", png_file});
        if (rc != 0)
          throw std::runtime_error("--png: " + script + " failed (exit " + std::to_string(rc) + "); the CSV " +
                                   out_file + " was written, no PNG");
        std::printf("wrote %s\n", png_file.c_str());
      }
      return 0;
    }
    const rc::rom::Scene scene = rc::rom::parse_scene(scene_file);
    if (spec->parsed() && spec_confirm) confirm_req.json = json;
    if (confirm->parsed() || (spec->parsed() && spec_confirm))
      return rc::rom::confirm_roots(scene, confirm_req, std::cout) > 0 ? 3 : 0;
    if (!spec->parsed() && scene.run.present && scene.run.nonlinear()) return run_nonlinear(scene, out_file);
    const rc::rom::ChainModel model = rc::rom::build_model(scene);
    if (spec->parsed()) {
      rc::rom::Spectrum sp = rc::rom::compute_spectrum(model);
      if (rc::rom::has_companions(scene))
        rc::rom::mark_companion_shifts(
            sp, rc::rom::compute_spectrum(rc::rom::build_model(rc::rom::with_companions(scene))));
      if (json) std::cout << rc::rom::spectrum_json(model, sp) << "\n";
      else rc::rom::print_spectrum(std::cout, model, sp);
    } else {
      if (!scene.run.present) throw std::runtime_error(scene_file + ": run: missing [run] section");
      // An unstable scene is integrated all the same (its growth may be what the user studies), but said first:
      // the linear model's tilts then grow without bound (fuzz: 30 000 degrees without a word).
      double growth_over_run = 0;  // e-folds of the fastest growing root over the run
      try {
        const rc::rom::Verdict v = rc::rom::compute_verdict(model);
        if (!v.stable) growth_over_run = (model.dissipative() ? v.growth : v.margin) * scene.run.t_end;
        if (!v.stable)
          std::fprintf(stderr, "chain-rom: warning: the scene is unstable (%s %.6g %s): the linearised tilts grow "
                               "without bound and leave the model's small-angle range\n",
                       model.dissipative() ? "largest growth rate" : "margin, largest |Im sigma|", v.margin,
                       model.dissipative() ? "1/s" : "rad/s");
      } catch (const std::runtime_error&) {
        // No verdict (the eigen-solver failed): the propagation reports its own trouble.
      }
      rc::rom::History h = rc::rom::propagate(model, scene);
      // Is the amplitude small enough for the linear model? Measured against the nonlinear chain.
      const bool exact = h.method_used.rfind("exact", 0) == 0;  // then the check reuses this history
      // Tilts that grow more than tenfold during the run leave any small-angle range whatever the amplitude: the check
      // (a nonlinear run, seconds) could only say so, and is skipped with that reason (docs/rom.md, "Nonlinear chain").
      rc::rom::LinearValidity validity;
      if (growth_over_run > std::log(10.0)) {
        char why[200];
        std::snprintf(why, sizeof why, "the scene is unstable and its tilts grow by e^%.3g during the run, out of the "
                                       "small-angle range at any amplitude", growth_over_run);
        validity.why_not = std::string(why) + "; [run] model = \"nonlinear\" integrates the full motion";
      }
      else
        validity = rc::rom::linear_validity(scene, model, exact ? &h : nullptr);
      if (validity.measured) {
        h.nonlinear_difference = validity.difference;
        h.amplitude_at_limit = validity.amplitude_at_limit;
        if (validity.difference > rc::rom::kLinearValidityLimit)
          std::fprintf(stderr, "chain-rom: warning: at this amplitude (%.3g rad) the tilts differ from the nonlinear chain's "
                               "by %.2g %%: the linear model holds to 1 %% below about %.3g rad (docs/rom.md, "
                               "\"Nonlinear chain\"); [run] model = \"nonlinear\" integrates the full motion\n",
                       validity.amplitude, 100 * validity.difference,
                       validity.amplitude_at_limit);
      } else {
        h.validity_note = validity.why_not;
      }
      // A trajectory that left the double range (a scene of extreme magnitudes) is reported, never written.
      const bool energy_finite = model.viscous ||  // no energy with viscous tanks (output.cpp writes none)
                                 std::all_of(h.H.begin(), h.H.end(), [](double e) { return std::isfinite(e); });
      if (!h.u.allFinite() || !h.z.allFinite() || !energy_finite)
        throw std::runtime_error("the trajectory is not finite (method " + h.method_used +
                                 "): the scene's magnitudes leave double precision; nothing written");
      rc::rom::write_history(model, h, out_file);
      std::cout << "wrote " << out_file << ": " << h.t.size() << " samples, method " << h.method_used
                << ", " << h.wall_seconds << " s (CPU " << h.cpu_seconds << " s)\n";
      if (validity.measured)
        std::cout << "validity: the nonlinear chain differs by "
                  << validity.difference
                  << " relative (1 % at about " << validity.amplitude_at_limit << " rad; checked in "
                  << validity.seconds << " s)\n";
      else
        std::cout << "validity: not measured (" << validity.why_not << ")\n";
      if (model.viscous) {
        const rc::rom::EnergyBudget& b = h.budget;
        const rc::rom::EnergyBalance& e = h.balance;
        if (!e.empty())
          std::cout << "energy: H(0) = " << e.energy.front() << ", H(end) = " << e.energy.back()
                    << " J, dissipated " << e.dissipated.back() << " J (fluid " << e.fluid_dissipated
                    << " J); dH/dt = -(joint power + fluid dissipation) to " << e.residual
                    << " on the samples (docs/rom.md, \"Galerkin tanks\")\n";
        else
          std::cout << "energy: no integral with these viscous tanks: " << rc::rom::galerkin_energy_unavailable(model)
                    << "\n";
        std::cout << "energy budget of the chain with its fluid frozen: H_b(0) = " << b.frozen_energy.front()
                  << ", H_b(end) = " << b.frozen_energy.back() << " J, work taken by the fluid " << b.fluid_work.back()
                  << " J, friction " << b.friction_work << " J; dH_b/dt = -(friction + fluid power) to "
                  << b.balance_residual << " on the samples (docs/rom.md, \"Energy budget\")\n";
      } else {
        std::cout << "energy: H(0) = " << h.H.front() << ", H(end) = " << h.H.back() << ", "
                  << (model.has_friction() ? "largest relative increase per step " : "largest relative drift ")
                  << h.max_energy_drift << "\n";
      }
    }
  } catch (const std::exception& e) {
    std::string msg = e.what();
    for (auto& ch : msg) if (ch == '\n') ch = ' ';
    std::cerr << "chain-rom: error: " << msg << "\n";
    return 1;
  }
  return 0;
}
